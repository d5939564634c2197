# facet batch's exit codes for the files of the command itself, as facet
# diff's: a job file, a --junit report or a --merge input that cannot be
# read or written is FILE ERROR (4), on one line naming it; a --junit write
# that fails after the jobs keeps their worse code; an empty or oversized
# --shard is a usage error (64). Run with -DFACET=... -DDIR=...
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
file(WRITE ${DIR}/jobs.jsonl "{\"scene\":\"builtin:cube\",\"size\":\"16x16\",\"output\":\"cube.png\"}\n{\"scene\":\"gone.gltf\",\"output\":\"gone.png\"}\n")

# one_line(REGEX): stderr is one line matching REGEX.
function(one_line regex)
  string(STRIP "${err}" text)
  if(NOT text MATCHES "${regex}" OR text MATCHES "\n")
    message(FATAL_ERROR "expected one line matching ${regex}${report}")
  endif()
endfunction()

# An empty argument (an unset $SHARD), through bash: CMake drops empty list items.
facet_run_command(COMMAND bash -c "\"$0\" batch \"$1\" --dry-run --shard ''" ${FACET} ${DIR}/jobs.jsonl EXPECT 64)
one_line("^facet: --shard '': expected I/N")
facet_run_command(COMMAND ${FACET} batch ${DIR}/jobs.jsonl --dry-run --shard 0/1000000000 EXPECT 64)
one_line("^facet: --shard '0/1000000000': at most 999999999 shards")

facet_run_command(COMMAND ${FACET} batch ${DIR}/missing.jsonl EXPECT 4)
one_line("^facet: .*missing.jsonl: no such file$")
facet_run_command(COMMAND ${FACET} batch ${DIR}/jobs.jsonl --junit ${DIR}/no-folder/report.xml EXPECT 4)
one_line("^facet: .*no-folder/report.xml: the folder .*no-folder does not exist$")
if(NOT EXISTS ${DIR}/jobs.jsonl OR EXISTS ${DIR}/cube.png)
  message(FATAL_ERROR "an unwritable --junit is refused before any job runs${report}")
endif()
facet_run_command(COMMAND ${FACET} batch --merge ${DIR}/merged.xml ${DIR}/missing.xml EXPECT 4)
one_line("^facet: .*missing.xml: no such file$")
if(EXISTS ${DIR}/merged.xml)
  message(FATAL_ERROR "--merge wrote a report from a missing input")
endif()

# The jobs run (one FILE ERROR of its own), then the report cannot be
# written: the line says so, and the code is still the jobs' worst, 4.
if(EXISTS /dev/full)
  facet_run_command(COMMAND ${FACET} batch ${DIR}/jobs.jsonl --junit /dev/full EXPECT 4)
  if(NOT err MATCHES "facet: /dev/full: write failed" OR NOT EXISTS ${DIR}/cube.png)
    message(FATAL_ERROR "a failed --junit write at the end: not named, or the jobs did not run${report}")
  endif()
endif()
message(STATUS "batch: file errors 4, a failed report keeps the jobs' code, bad shards 64")
