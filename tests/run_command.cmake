# Shared by the scripts that run a command as a test (expect_error.cmake,
# expect_output.cmake, compare/expect_diff.cmake): run it and hold it to its
# exit code. A signal (crash, abort) never passes: execute_process then
# reports a text such as "Segmentation fault" instead of a number.
#   facet_run_command(COMMAND <words> EXPECT <code> [WORKING_DIRECTORY dir])
# sets rc, out and err in the caller, and stops with the output when the
# code differs.
function(facet_run_command)
  cmake_parse_arguments(PARSE_ARGV 0 R "" "EXPECT;WORKING_DIRECTORY" "COMMAND")
  if(NOT R_WORKING_DIRECTORY)
    set(R_WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  endif()
  execute_process(COMMAND ${R_COMMAND} WORKING_DIRECTORY ${R_WORKING_DIRECTORY} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  # xvfb-run exits 5, in place of the command's own code, when it cannot
  # remove its temporary folder afterwards (Debian 12's xvfb-run removes it
  # before it stops Xvfb, which may still write there): the virtual display's
  # housekeeping, not facet. The command runs once more; twice is a failure.
  if(rc EQUAL 5 AND err MATCHES "xvfb-run: error: problem while cleaning up temporary directory")
    message(STATUS "xvfb-run could not clean up its temporary folder; running the command again")
    execute_process(COMMAND ${R_COMMAND} WORKING_DIRECTORY ${R_WORKING_DIRECTORY} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  endif()
  set(report "\nexit ${rc}\nstdout:\n${out}\nstderr:\n${err}")
  if(NOT rc MATCHES "^[0-9]+$")
    message(FATAL_ERROR "the command did not exit, it ended with: ${rc}${report}")
  endif()
  if(NOT rc EQUAL R_EXPECT)
    message(FATAL_ERROR "expected exit code ${R_EXPECT}, got ${rc}${report}")
  endif()
  set(rc "${rc}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
  set(report "${report}" PARENT_SCOPE)
endfunction()
