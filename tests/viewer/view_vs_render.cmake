# `facet view --screenshot` against `facet render --backend gl` with the same
# scene, settings and size (see CMakeLists.txt). Defines: FACET, XVFB_RUN,
# OUT (a path prefix for the images), ARGS and CHANGED (|-separated).
string(REPLACE "|" ";" args "${ARGS}")
string(REPLACE "|" ";" changed "${CHANGED}")
set(size 320x240)  # small: llvmpipe draws it in tens of milliseconds

include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)

function(run what)
  facet_run_command(COMMAND ${ARGN} EXPECT 0)
  message(STATUS "${what}: ${out}")
endfunction()

# `facet diff`'s exit code for two images, held to what the backends are
# held to (--agreement: renderer/compare/backend_agreement.h, every byte
# equal). A heat map goes beside the images.
function(compare expected actual heatmap result)
  execute_process(COMMAND ${FACET} diff ${expected} ${actual} --agreement -o ${heatmap}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}${err}")
  set(${result} ${rc} PARENT_SCOPE)
endfunction()

# The viewer and the headless renderer on the same arguments must agree.
function(view_and_render tag)
  set(view ${OUT}_${tag}_view.png)
  set(render ${OUT}_${tag}_render.png)
  file(REMOVE ${view} ${render})
  run("facet view (${tag})" ${XVFB_RUN} -a ${FACET} view --size ${size} --frames 3 --screenshot ${view} ${ARGN})
  run("facet render (${tag})" ${FACET} render --backend gl --size ${size} -o ${render} ${ARGN})
  compare(${render} ${view} ${OUT}_${tag}_heatmap.png rc)
  if(NOT rc EQUAL 0)  # 0 PASS: every byte equal
    message(FATAL_ERROR "the viewer's screenshot ${view} and facet render's ${render} differ (facet diff exit ${rc})")
  endif()
endfunction()

view_and_render(first ${args})
if(changed)
  view_and_render(changed ${args} ${changed})
  compare(${OUT}_first_view.png ${OUT}_changed_view.png ${OUT}_change_heatmap.png rc)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "${changed} did not change the viewer's image (facet diff exit ${rc}, expected 2: they differ)")
  endif()
endif()
