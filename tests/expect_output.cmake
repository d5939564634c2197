# A command that must succeed, checked for any command: run COMMAND (its
# words joined by '|') and require
#  - the exit code EXIT (default 0; never a signal: run_command.cmake);
#  - when STDOUT (STDERR) is given, stdout (stderr) matching that regular expression;
#  - when OUTPUT is given, that file written by the run (it is removed first);
#  - when GOLDEN is given, OUTPUT equal to GOLDEN byte for byte in every
#    pixel (`FACET diff --agreement`, which reads both PNGs);
#  - when DIFFERENT is given, OUTPUT not equal to that PNG (the flag under
#    test changed the image).
include(${CMAKE_CURRENT_LIST_DIR}/run_command.cmake)
string(REPLACE "|" ";" command "${COMMAND}")
if(NOT DEFINED EXIT)
  set(EXIT 0)
endif()
if(OUTPUT)
  file(REMOVE "${OUTPUT}")
endif()
facet_run_command(COMMAND ${command} EXPECT ${EXIT})
if(DEFINED STDOUT AND NOT out MATCHES "${STDOUT}")
  message(FATAL_ERROR "stdout does not match '${STDOUT}'${report}")
endif()
if(DEFINED STDERR AND NOT err MATCHES "${STDERR}")
  message(FATAL_ERROR "stderr does not match '${STDERR}'${report}")
endif()
if(OUTPUT AND NOT EXISTS "${OUTPUT}")
  message(FATAL_ERROR "the run did not write ${OUTPUT}${report}")
endif()
# facet diff --agreement of OUTPUT against a PNG must exit with `code` (0: equal, 2: different).
function(compare_with png code what)
  execute_process(COMMAND ${FACET} diff ${png} ${OUTPUT} --agreement RESULT_VARIABLE diff_rc OUTPUT_VARIABLE diff_out ERROR_VARIABLE diff_err)
  if(NOT diff_rc EQUAL code)
    message(FATAL_ERROR "${OUTPUT} ${what} ${png} (facet diff exit ${diff_rc}, expected ${code}):\n${diff_out}${diff_err}")
  endif()
endfunction()
if(GOLDEN)
  compare_with(${GOLDEN} 0 "differs from")
endif()
if(DIFFERENT)
  compare_with(${DIFFERENT} 2 "is the same image as")
endif()
message(STATUS "exit ${rc}: ${out}")
