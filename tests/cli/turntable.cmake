# facet render --turntable 4 with an -o template, in a fresh folder OUT:
#  - exactly the four files the template names, and a line for each frame;
#  - frame 0 byte for byte the plain render (no move, no file of its own
#    camera), every two frames different images;
#  - frame 1 (90 degrees) the same as --camera-azimuth 90 and as F3D's
#    spelling --camera-azimuth-angle=90;
#  - a turntable's frame 0 with --camera-elevation the plain render with it.
# Defines: FACET, OUT.
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(render ${FACET} render --backend cpu --size 96x72)

facet_run_command(COMMAND ${render} --turntable 4 -o ${OUT}/tt_{scene}_{backend}_{frame}.png EXPECT 0)
if(NOT out MATCHES "turntable: 4 frames, 90 degrees apart.*frame 0 azimuth +0\\.000 .*frame 3 azimuth +270\\.000 [^\n]*tt_default_cpu_3\\.png\n.*frames .* ms, median [0-9.]+ ms a frame")
  message(FATAL_ERROR "no line for each frame${report}")
endif()
file(GLOB written RELATIVE ${OUT} ${OUT}/*)
list(SORT written)
if(NOT written STREQUAL "tt_default_cpu_0.png;tt_default_cpu_1.png;tt_default_cpu_2.png;tt_default_cpu_3.png")
  message(FATAL_ERROR "the turntable wrote '${written}', not the four names its template gives")
endif()

# facet diff --agreement A B must exit with `code` (0: equal, 2: different).
function(compare a b code)
  facet_run_command(COMMAND ${FACET} diff ${OUT}/${a} ${OUT}/${b} --agreement EXPECT ${code})
endfunction()

facet_run_command(COMMAND ${render} -o ${OUT}/plain.png EXPECT 0)
compare(plain.png tt_default_cpu_0.png 0)
foreach(pair 0:1 0:2 0:3 1:2 1:3 2:3)
  string(REPLACE ":" ";" pair ${pair})
  list(GET pair 0 a)
  list(GET pair 1 b)
  compare(tt_default_cpu_${a}.png tt_default_cpu_${b}.png 2)
endforeach()

facet_run_command(COMMAND ${render} --camera-azimuth 90 -o ${OUT}/azimuth90.png EXPECT 0)
compare(azimuth90.png tt_default_cpu_1.png 0)
facet_run_command(COMMAND ${render} --camera-azimuth-angle=90 -o ${OUT}/azimuth_angle90.png EXPECT 0)
compare(azimuth_angle90.png tt_default_cpu_1.png 0)

facet_run_command(COMMAND ${render} --camera-elevation 30 -o ${OUT}/elevation30.png EXPECT 0)
compare(elevation30.png plain.png 2)
facet_run_command(COMMAND ${render} --camera-elevation 30 --turntable 2 -o ${OUT}/raised_{n}.png EXPECT 0)
compare(elevation30.png raised_0.png 0)
compare(raised_0.png raised_1.png 2)
message(STATUS "${written}")
