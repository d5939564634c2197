# `facet view --screenshot --with-panel` writes the whole window: the panel
# must be in it, so it differs from the 3D view alone. Defines: FACET,
# XVFB_RUN, OUT (a path prefix for the images).
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
set(plain ${OUT}_plain.png)
set(panel ${OUT}_panel.png)
file(REMOVE ${plain} ${panel})
foreach(flags IN ITEMS "--screenshot|${plain}" "--screenshot|${panel}|--with-panel")
  string(REPLACE "|" ";" flags "${flags}")
  facet_run_command(COMMAND ${XVFB_RUN} -a -s "-screen 0 1024x768x24" ${FACET} view --size 800x600 --frames 2 ${flags} EXPECT 0)
endforeach()
execute_process(COMMAND ${FACET} diff ${plain} ${panel} -o ${OUT}_heatmap.png RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "the screenshot with the panel equals the one without (facet diff exit ${rc}): ImGui drew nothing")
endif()
