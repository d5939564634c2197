# facet bench's lean column draws the picture the CPU rasterizer draws
# (bench/bench_lean_gl.cpp): its own shader maths, so not byte for byte, but
# close. Defines: FACET, OUT (a folder, made afresh).
#
# Measured at 320x180 (Mesa 22.3.6 llvmpipe): mean difference 0.119 levels
# (sphere-100k-shadow) and 0.086 (default), the largest channel difference
# 1 level, no pixel over 16 levels. The limits below leave room for another
# llvmpipe's rounding; neither a lean shader without its diffuse term (36.0
# and 41.4 levels, 53 % and 57 % of pixels over 16) nor a black image (94.2
# and 104.5 levels, every pixel over 16) passes them.
#
# default-aa4 is held to the same limits at 640x360: lean's four samples are
# llvmpipe's multisampling positions, not facet's grid, so an edge pixel
# covers its two sides in other shares. Those pixels are the ones over 16
# levels, and their share halves as the size doubles (0.543 % at 320x180,
# 0.275 % at 640x360; mean difference 0.278 and 0.191 levels).
#
# lean shades every sample of an anti-aliased frame (the course's
# supersampling), lean-msaa once a pixel: their default-aa4 images differ
# (5,440 of 57,600 pixels at 320x180), and their single-sample ones do not.
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
set(max_mean 1.0)        # levels, R, G, B averaged over every pixel
set(max_over16 0.5)      # percent of pixels with a channel more than 16 levels off

file(REMOVE_RECURSE ${OUT})

# Benchmarks `scenes` at `size` with `backends` (one frame, PNGs into OUT/size), and holds lean to the CPU's image on each.
function(lean_against_cpu size scenes backends)
  set(dir ${OUT}/${size})
  file(MAKE_DIRECTORY ${dir})
  string(REPLACE ";" "," scene_list "${scenes}")
  facet_run_command(COMMAND ${FACET} bench --scenes ${scene_list} --backends ${backends} --size ${size} --frames 1 --warmup 0
    --startup-runs 0 --no-memory --out ${dir} EXPECT 0)
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
      message(FATAL_ERROR "${scene} at ${size}: lean differs from cpu by ${mean} levels on average, ${over16} % of pixels over 16 levels "
                          "(limits ${max_mean} and ${max_over16})${bench_report}")
    endif()

    # The PNGs --out wrote, held to the same share by facet diff on its own.
    string(REPLACE "," ";" backend_list "${backends}")
    foreach(backend ${backend_list})
      if(NOT EXISTS ${dir}/${scene}-${backend}.png)
        message(FATAL_ERROR "the bench did not write ${dir}/${scene}-${backend}.png${bench_report}")
      endif()
    endforeach()
    facet_run_command(COMMAND ${FACET} diff ${dir}/${scene}-cpu.png ${dir}/${scene}-lean.png --fail 16/255 --failpercent ${max_over16}
      --warn 16/255 --warnpercent ${max_over16} EXPECT 0)
    message(STATUS "${scene} at ${size}: lean vs cpu mean difference ${mean} levels, ${over16} % over 16 levels")
  endforeach()
endfunction()

lean_against_cpu(320x180 "sphere-100k-shadow;default" cpu,lean,lean-msaa)
lean_against_cpu(640x360 "default-aa4" cpu,lean)

# Every sample shaded, or once a pixel: facet diff exits 2 where any channel differs, 0 where none does.
facet_run_command(COMMAND ${FACET} bench --scenes default-aa4 --backends lean,lean-msaa --size 320x180 --frames 1 --warmup 0
  --startup-runs 0 --no-memory --out ${OUT}/320x180 EXPECT 0)
facet_run_command(COMMAND ${FACET} diff ${OUT}/320x180/default-aa4-lean.png ${OUT}/320x180/default-aa4-lean-msaa.png EXPECT 2)
if(NOT out MATCHES "differing pixels ([0-9]+)")
  message(FATAL_ERROR "facet diff printed no count of differing pixels${report}")
endif()
message(STATUS "default-aa4 at 320x180: lean (every sample shaded) and lean-msaa differ on ${CMAKE_MATCH_1} pixels")
facet_run_command(COMMAND ${FACET} diff ${OUT}/320x180/default-lean.png ${OUT}/320x180/default-lean-msaa.png EXPECT 0)
