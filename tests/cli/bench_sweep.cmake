# facet bench --sweep --sweep-quick, checked as a reader uses it: run
# COMMAND (its words joined by '|'; it ends with --plot PLOT) for BACKENDS
# (joined by '|'), then require
#  - one table row per point of the quick sweep, no other, each with a
#    time and a peak memory figure for every backend;
#  - peak memory that grows with the triangles (the child's own figure, not
#    this process's: bench measures before it grows);
#  - PLOT written and well-formed XML (Python's parser), with a panel per
#    axis for time and for memory, and a line per backend in each.
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
string(REPLACE "|" ";" command "${COMMAND}")
string(REPLACE "|" ";" backends "${BACKENDS}")
file(REMOVE "${PLOT}")
facet_run_command(COMMAND ${command} EXPECT 0)

# The quick sweep's points (bench/bench_sweep.cpp), axis by axis.
set(points triangles=80 triangles=1k triangles=10k triangles=100k
  pixels=40x30 pixels=80x60 pixels=160x120 pixels=320x240 pixels=640x480
  lights=1 lights=2 lights=4 lights=8)
# A backend's two columns: median ms per frame, peak MB.
set(columns "")
foreach(backend IN LISTS backends)
  string(APPEND columns " +([0-9]+\\.[0-9]+) +([0-9]+)")
endforeach()
string(REGEX MATCHALL "\n(triangles|pixels|lights) [^\n]*" rows "${out}")
list(LENGTH rows row_count)
list(LENGTH points point_count)
if(NOT row_count EQUAL point_count)
  message(FATAL_ERROR "${row_count} table rows for ${point_count} points${report}")
endif()
set(i 0)
foreach(point IN LISTS points)
  list(GET rows ${i} row)
  string(REPLACE "=" ";" parts "${point}")
  list(GET parts 0 axis)
  list(GET parts 1 name)
  if(NOT row MATCHES "^\n${axis} +${name} +[0-9]+ +[0-9]+x[0-9]+ .*[^ ]${columns}$")
    message(FATAL_ERROR "row ${i} is not ${point} with every backend's ms and MB:${row}${report}")
  endif()
  if(point STREQUAL "triangles=80")
    set(fewest_mb ${CMAKE_MATCH_2})
  elseif(point STREQUAL "triangles=100k")
    set(most_mb ${CMAKE_MATCH_2})
  endif()
  math(EXPR i "${i} + 1")
endforeach()
if(NOT fewest_mb LESS most_mb)
  message(FATAL_ERROR "peak memory does not grow from 80 to 100k triangles (${fewest_mb} -> ${most_mb} MB)${report}")
endif()

if(NOT EXISTS "${PLOT}")
  message(FATAL_ERROR "the sweep did not write ${PLOT}${report}")
endif()
execute_process(COMMAND ${PYTHON} -c "import sys, xml.etree.ElementTree as t; t.parse(sys.argv[1])" "${PLOT}"
  RESULT_VARIABLE xml_rc ERROR_VARIABLE xml_err)
if(NOT xml_rc EQUAL 0)
  message(FATAL_ERROR "${PLOT} is not well-formed XML: ${xml_err}")
endif()
file(READ "${PLOT}" svg)
foreach(text "triangles: " "pixels: " "spot lights: " "ms per frame" "peak MB")
  string(FIND "${svg}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${PLOT} has no '${text}'")
  endif()
endforeach()
foreach(backend IN LISTS backends)
  if(NOT svg MATCHES ">${backend}</text>")
    message(FATAL_ERROR "${PLOT} has no legend entry for ${backend}")
  endif()
endforeach()
# Three axes, time and memory: six panels, each with a line per backend.
string(REGEX MATCHALL "fill=\"none\" stroke=" lines "${svg}")
list(LENGTH lines line_count)
list(LENGTH backends backend_count)
math(EXPR expected "6 * ${backend_count}")
if(NOT line_count EQUAL expected)
  message(FATAL_ERROR "${PLOT} draws ${line_count} lines, expected ${expected} (6 panels x ${backend_count} backends)")
endif()
message(STATUS "${row_count} rows, ${line_count} lines in ${PLOT}")
