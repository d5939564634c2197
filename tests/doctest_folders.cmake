# Which folder of tests/ each case of a doctest executable comes from, for
# its labels (tests/labels.cmake): run after each build of it, it writes
# set(TARGET_IN_FOLDER ...) with the ctest names of the cases in
# tests/FOLDER, as doctest's --source-file filter finds them.
#   cmake -DEXECUTABLE=... -DTARGET=... [-DPREFIX=...] -DFOLDERS=a,b -DOUT=file -P doctest_folders.cmake
string(REPLACE "," ";" FOLDERS "${FOLDERS}")
set(text "# Written by tests/doctest_folders.cmake after each build of ${TARGET}.\n")
foreach(folder IN LISTS FOLDERS)
  execute_process(COMMAND ${EXECUTABLE} --list-test-cases --source-file=*/tests/${folder}/*
                  OUTPUT_VARIABLE output RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${EXECUTABLE} --list-test-cases: exit ${result}\n${output}")
  endif()
  string(APPEND text "set(${TARGET}_IN_${folder}")
  string(REPLACE "\n" ";" lines "${output}")
  foreach(line IN LISTS lines)  # doctest's listing, read as doctestAddTests.cmake reads it
    if(line AND NOT line MATCHES "^(=+|\\[doctest\\] .*)$")
      string(APPEND text "\n  [==[${PREFIX}${line}]==]")
    endif()
  endforeach()
  string(APPEND text ")\n")
endforeach()
file(WRITE ${OUT} "${text}")
