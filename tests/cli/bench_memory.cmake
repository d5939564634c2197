# facet bench's peak memory column is each child's own figure: run COMMAND
# (its words joined by '|'; --scenes sphere-1m,fill-10x --backends cpu) and
# require fill-10x's peak below sphere-1m's. Measured after sphere-1m had
# grown this process, fill-10x would inherit its peak (child_process.h).
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
string(REPLACE "|" ";" command "${COMMAND}")
facet_run_command(COMMAND ${command} EXPECT 0)
foreach(scene sphere-1m fill-10x)
  # the cpu row: ms/frame, the spread, Mtri/s, then peak MB
  if(NOT out MATCHES "\n${scene}: [^\n]*\n[^\n]*\n  cpu +[0-9.]+ +[0-9.]+\\.\\.[0-9.]+ \\([0-9.]+\\.\\.[0-9.]+\\) +[0-9.]+ +([0-9]+) ")
    message(FATAL_ERROR "no peak MB for ${scene}${report}")
  endif()
  set(${scene}_mb ${CMAKE_MATCH_1})
endforeach()
if(NOT fill-10x_mb LESS sphere-1m_mb)
  message(FATAL_ERROR "fill-10x peaks at ${fill-10x_mb} MB, sphere-1m at ${sphere-1m_mb} MB: not each child's own${report}")
endif()
message(STATUS "peak MB: sphere-1m ${sphere-1m_mb}, fill-10x ${fill-10x_mb}")
