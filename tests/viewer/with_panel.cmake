# `facet view --screenshot --with-panel` writes the whole window: the panel
# docked on the left, the 3D view beside it byte for byte as the screenshot
# of the view alone (nothing covers the picture); with --no-panel the window
# is the view alone. Defines: FACET, XVFB_RUN, CHECK (window_layout_check),
# OUT (a path prefix for the images).
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
foreach(layout IN ITEMS panel no-panel)
  set(plain ${OUT}_${layout}_view.png)
  set(window ${OUT}_${layout}_window.png)
  file(REMOVE ${plain} ${window})
  set(hide "")
  if(layout STREQUAL "no-panel")
    set(hide --no-panel)
  endif()
  foreach(flags IN ITEMS "--screenshot|${plain}" "--screenshot|${window}|--with-panel")
    string(REPLACE "|" ";" flags "${flags}")
    facet_run_command(COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x768x24" ${FACET} view --size 640x480 --frames 2 ${hide} ${flags} EXPECT 0)
  endforeach()
  facet_run_command(COMMAND ${CHECK} ${window} ${plain} ${layout} EXPECT 0)
  message(STATUS "${out}")
endforeach()
