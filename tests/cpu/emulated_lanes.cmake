# One build runs on any x86-64: facet under QEMU's user-mode emulation of a
# narrower CPU takes the lanes that CPU has, runs no instruction it lacks
# (QEMU would stop it with SIGILL) and writes the same bytes as the native
# run, at the widest lanes this CPU runs. CPU Opteron_G5 (AMD Piledriver:
# FMA, no AVX2) must take four lanes; CPU max (QEMU's own instructions:
# AVX2, no AVX-512) must take eight.
#   cmake -DFACET=... -DQEMU=qemu-x86_64 -DCPU=Opteron_G5 -DLANES=4 -DSCENE=... -DOUT=folder -P emulated_lanes.cmake
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
if(NOT EXISTS "${QEMU}")
  message(FATAL_ERROR "qemu-x86_64 not found: Debian's qemu-user runs this test (scripts/install-deps.sh installs it)")
endif()
file(MAKE_DIRECTORY ${OUT})
string(REGEX REPLACE "^.*[/:]" "" name "${SCENE}")
string(REGEX REPLACE "[.][^.]*$" "" name "${name}")
set(native ${OUT}/${name}-native-${CPU}.png)
set(emulated ${OUT}/${name}-${CPU}.png)
file(REMOVE ${native} ${emulated})
set(render render ${SCENE} --backend cpu --size 160x120 --threads 2)
facet_run_command(COMMAND ${FACET} ${render} -o ${native} EXPECT 0)
set(native_out "${out}")
facet_run_command(COMMAND ${QEMU} -cpu ${CPU} ${FACET} ${render} -o ${emulated} EXPECT 0)
if(NOT out MATCHES "cpu rasterizer, 2 threads, ${LANES} lanes")
  message(FATAL_ERROR "on an emulated ${CPU} the CPU backend should take ${LANES} lanes:\n${out}")
endif()
if(NOT native_out MATCHES "cpu rasterizer, 2 threads, (4|8|16) lanes")
  message(FATAL_ERROR "the native run names no lane width:\n${native_out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${native} ${emulated} RESULT_VARIABLE different)
if(different)
  message(FATAL_ERROR "on an emulated ${CPU} the image differs from the native run's (${native}, ${emulated})")
endif()
