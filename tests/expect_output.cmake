# A command that must succeed, checked for any command: run COMMAND (its
# words joined by '|') and require
#  - the exit code EXIT (default 0; a signal never passes);
#  - when STDOUT is given, stdout matching that regular expression;
#  - when OUTPUT is given, that file written by the run (it is removed first);
#  - when GOLDEN is given, OUTPUT equal to GOLDEN byte for byte in every
#    pixel (`FACET diff --agreement`, which reads both PNGs);
#  - when DIFFERENT is given, OUTPUT not equal to that PNG (the flag under
#    test changed the image).
string(REPLACE "|" ";" command "${COMMAND}")
if(NOT DEFINED EXIT)
  set(EXIT 0)
endif()
if(OUTPUT)
  file(REMOVE "${OUTPUT}")
endif()
execute_process(COMMAND ${command} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "the command did not exit, it ended with: ${rc}\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT rc EQUAL EXIT)
  message(FATAL_ERROR "expected exit code ${EXIT}, got ${rc}\nstdout: ${out}\nstderr: ${err}")
endif()
if(DEFINED STDOUT AND NOT out MATCHES "${STDOUT}")
  message(FATAL_ERROR "stdout does not match '${STDOUT}':\n${out}\nstderr: ${err}")
endif()
if(OUTPUT AND NOT EXISTS "${OUTPUT}")
  message(FATAL_ERROR "the run did not write ${OUTPUT}\nstdout: ${out}\nstderr: ${err}")
endif()
if(GOLDEN)
  execute_process(COMMAND ${FACET} diff ${GOLDEN} ${OUTPUT} --agreement RESULT_VARIABLE diff_rc OUTPUT_VARIABLE diff_out ERROR_VARIABLE diff_err)
  if(NOT diff_rc EQUAL 0)
    message(FATAL_ERROR "${OUTPUT} differs from ${GOLDEN} (facet diff exit ${diff_rc}):\n${diff_out}${diff_err}")
  endif()
endif()
if(DIFFERENT)
  execute_process(COMMAND ${FACET} diff ${DIFFERENT} ${OUTPUT} --agreement RESULT_VARIABLE diff_rc OUTPUT_VARIABLE diff_out ERROR_VARIABLE diff_err)
  if(NOT diff_rc EQUAL 2)
    message(FATAL_ERROR "${OUTPUT} is the same image as ${DIFFERENT} (facet diff exit ${diff_rc}, expected 2):\n${diff_out}${diff_err}")
  endif()
endif()
message(STATUS "exit ${rc}: ${out}")
