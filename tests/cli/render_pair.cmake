# facet render of one scene with both backends at one size, then
# `facet diff --fail 0 --warn 0` of the two PNGs: every byte must be equal.
# Defines: FACET, SCENE, SIZE, OUT (a path prefix for the two images).
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
foreach(backend gl cpu)
  file(REMOVE ${OUT}_${backend}.png)
  facet_run_command(COMMAND ${FACET} render ${SCENE} --backend ${backend} --size ${SIZE} -o ${OUT}_${backend}.png EXPECT 0)
endforeach()
facet_run_command(COMMAND ${FACET} diff ${OUT}_cpu.png ${OUT}_gl.png --fail 0 --warn 0 EXPECT 0)
if(NOT out MATCHES "PASS")
  message(FATAL_ERROR "facet diff did not pass:${report}")
endif()
message(STATUS "${out}")
