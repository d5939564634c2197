# Bad files dropped on the window (--drop): a broken glTF and a settings
# file with an unknown key. Each gets one line on stderr naming the file, the
# window keeps running with the previous scene and settings (the screenshot
# equals one taken without the drops), and the exit is 0. Defines: FACET,
# XVFB_RUN, OUT (a path prefix), GLTF, SETTINGS (the bad files).
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
set(before ${OUT}_before.png)
set(after ${OUT}_after.png)
file(REMOVE ${before} ${after})
facet_run_command(COMMAND ${XVFB_RUN} -a ${FACET} view --size 160x120 --frames 4 --screenshot ${before} EXPECT 0)
facet_run_command(COMMAND ${XVFB_RUN} -a ${FACET} view --size 160x120 --frames 4 --screenshot ${after} --drop ${GLTF} --drop ${SETTINGS} EXPECT 0)
string(STRIP "${err}" lines)
string(REGEX MATCHALL "[^\n]+" lines "${lines}")
list(LENGTH lines count)
if(NOT count EQUAL 2)
  message(FATAL_ERROR "expected two lines on stderr, one per bad file, got:\n${err}")
endif()
list(GET lines 0 first)
list(GET lines 1 second)
if(NOT first MATCHES "^facet: view: .*BoxTextured.gltf: " OR NOT second MATCHES "^facet: view: .*bad_key.json.*shadows.pcf")
  message(FATAL_ERROR "stderr does not name the files and their problems:\n${err}")
endif()
execute_process(COMMAND ${FACET} diff ${before} ${after} --agreement RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the bad drops changed the picture (facet diff exit ${rc}):\n${out}")
endif()
message(STATUS "${err}")
