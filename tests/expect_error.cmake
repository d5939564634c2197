# The contract for bad input, checked for any command: run COMMAND (its
# words joined by '|'), with `cmake -E env ENV` when ENV is given (words
# joined by '|', e.g. K=V or --unset=K), and require a non-zero exit, exactly
# one line on stderr, that line matching PATTERN, and, when OUTPUT is given,
# no file left at OUTPUT.
string(REPLACE "|" ";" command "${COMMAND}")
if(ENV)
  string(REPLACE "|" ";" env "${ENV}")
  set(command ${CMAKE_COMMAND} -E env ${env} ${command})
endif()
if(OUTPUT)
  file(REMOVE "${OUTPUT}")
endif()
execute_process(COMMAND ${command} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit, got 0\nstdout: ${out}\nstderr: ${err}")
endif()
string(STRIP "${err}" err_stripped)
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
