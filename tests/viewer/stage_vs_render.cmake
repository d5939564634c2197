# Each stage the viewer shows over its 3D view (--stage, from either
# backend) against `facet render --output-stage` of the same scene, settings
# and size: every byte equal. Defines: FACET, XVFB_RUN, OUT (a path prefix).
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
set(size 240x180)
foreach(case IN ITEMS "depth|gl" "normals|cpu" "shadow-map|gl" "light-0|cpu" "overdraw|gl" "normals|gl|--set|shading=flat")
  string(REPLACE "|" ";" case "${case}")
  list(POP_FRONT case stage source)
  set(view ${OUT}_${stage}_${source}_view.png)
  set(render ${OUT}_${stage}_${source}_render.png)
  file(REMOVE ${view} ${render})
  facet_run_command(COMMAND ${XVFB_RUN} -a ${FACET} view --size ${size} --frames 2 --stage ${stage} --stage-source ${source} --screenshot ${view}
                    ${case} EXPECT 0)
  facet_run_command(COMMAND ${FACET} render --size ${size} --backend ${source} --output-stage ${stage} -o ${render} ${case} EXPECT 0)
  execute_process(COMMAND ${FACET} diff ${render} ${view} --agreement RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the viewer's ${stage} stage (${source}) differs from render --output-stage ${stage}:\n${out}")
  endif()
  message(STATUS "${stage} (${source}): the viewer's equals render's")
endforeach()
