# facet bench's lean column draws the picture the CPU rasterizer draws
# (app/bench_lean_gl.cpp): its own shader maths, so not byte for byte, but
# close. Defines: FACET, OUT (a folder, made afresh).
#
# Measured at 320x180 (Mesa 22.3.6 llvmpipe): mean difference 0.119 levels
# (sphere-100k-shadow) and 0.086 (default), the largest channel difference
# 1 level, no pixel over 16 levels. The limits below leave room for another
# llvmpipe's rounding; neither a lean shader without its diffuse term (36.0
# and 41.4 levels, 53 % and 57 % of pixels over 16) nor a black image (94.2
# and 104.5 levels, every pixel over 16) passes them.
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
set(max_mean 1.0)        # levels, R, G, B averaged over every pixel
set(max_over16 0.5)      # percent of pixels with a channel more than 16 levels off
set(scenes sphere-100k-shadow default)

file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
string(REPLACE ";" "," scene_list "${scenes}")
facet_run_command(COMMAND ${FACET} bench --scenes ${scene_list} --backends cpu,lean --size 320x180 --frames 1 --warmup 0
  --startup-runs 0 --no-memory --out ${OUT} EXPECT 0)
set(bench_out "${out}")
set(bench_report "${report}")

foreach(scene ${scenes})
  # The bench's own sanity line, the first after the scene's heading.
  string(FIND "${bench_out}" "\n${scene}: " at)
  if(at LESS 0)
    message(FATAL_ERROR "no table for ${scene}${bench_report}")
  endif()
  string(SUBSTRING "${bench_out}" ${at} -1 table)
  if(NOT table MATCHES "lean vs cpu: mean difference ([0-9.]+) levels, ([0-9.]+) % of pixels differ by more than 16 levels")
    message(FATAL_ERROR "no lean vs cpu line for ${scene}${bench_report}")
  endif()
  set(mean ${CMAKE_MATCH_1})
  set(over16 ${CMAKE_MATCH_2})
  if(NOT mean LESS max_mean OR NOT over16 LESS max_over16)
    message(FATAL_ERROR "${scene}: lean differs from cpu by ${mean} levels on average, ${over16} % of pixels over 16 levels "
                        "(limits ${max_mean} and ${max_over16})${bench_report}")
  endif()

  # The PNGs --out wrote, held to the same share by facet diff on its own.
  foreach(backend cpu lean)
    if(NOT EXISTS ${OUT}/${scene}-${backend}.png)
      message(FATAL_ERROR "the bench did not write ${OUT}/${scene}-${backend}.png${bench_report}")
    endif()
  endforeach()
  facet_run_command(COMMAND ${FACET} diff ${OUT}/${scene}-cpu.png ${OUT}/${scene}-lean.png --fail 16/255 --failpercent ${max_over16}
    --warn 16/255 --warnpercent ${max_over16} EXPECT 0)
  message(STATUS "${scene}: lean vs cpu mean difference ${mean} levels, ${over16} % over 16 levels")
endforeach()
