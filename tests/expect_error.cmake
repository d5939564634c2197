# The contract for bad input, checked for any command: run COMMAND (its
# words joined by '|'), with `cmake -E env ENV` when ENV is given (words
# joined by '|', e.g. K=V or --unset=K), and require
#  - the exit code EXIT (default 1; 64 for a command line that does not
#    parse), never a signal (run_command.cmake);
#  - exactly one line on stderr, matching PATTERN;
#  - when OUTPUT is given, no file left at OUTPUT (it is removed first).
include(${CMAKE_CURRENT_LIST_DIR}/run_command.cmake)
string(REPLACE "|" ";" command "${COMMAND}")
if(ENV)
  string(REPLACE "|" ";" env "${ENV}")
  set(command ${CMAKE_COMMAND} -E env ${env} ${command})
endif()
if(NOT DEFINED EXIT)
  set(EXIT 1)
endif()
if(OUTPUT)
  file(REMOVE "${OUTPUT}")
endif()
facet_run_command(COMMAND ${command} EXPECT ${EXIT})
string(STRIP "${err}" err_stripped)
if(err_stripped STREQUAL "")
  message(FATAL_ERROR "expected one line on stderr, got none${report}")
endif()
string(FIND "${err_stripped}" "\n" newline)
if(NOT newline EQUAL -1)
  message(FATAL_ERROR "expected one line on stderr, got:\n${err}")
endif()
if(NOT err_stripped MATCHES "${PATTERN}")
  message(FATAL_ERROR "stderr does not match '${PATTERN}':\n${err}")
endif()
if(OUTPUT AND EXISTS "${OUTPUT}")
  message(FATAL_ERROR "the failed run left ${OUTPUT} behind")
endif()
message(STATUS "exit ${rc}: ${err_stripped}")
