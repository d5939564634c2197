# facet batch as a user runs it (-DFACET, -DDIR, -DGOLDEN a PNG of the default
# scene at 64x48 that a CPU frame matches within one step):
#  - a 6-job file mixing cpu and gl, a comparison passing and one failing,
#    a line that is not JSON, an unknown key, a missing scene and an output
#    under a regular file: each bad job fails alone naming its line, the
#    others are written, the exit code is the worst job's (4);
#  - the JUnit report is well-formed XML (xmllint) with the counts, and a
#    JUnit consumer (junitparser, -DPYTHON) reads the same counts and results;
#  - --resume renders again when a file the settings name changes;
#  - --resume renders again an output whose image data is damaged;
#  - --resume skips every written job, and renders again after a settings
#    change or a new texture under a glTF (-DASSIMP: the assimp glTF2 models);
#  - --shard I/N (N = 1, 2, 3, 7) of a 20-job file lists every job exactly once,
#    and 0/0, 5/3, a/b are refused with 64;
#  - the merged reports of 3 shards equal the whole run's, times apart.
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
file(WRITE ${DIR}/blocker "a regular file: nothing can be made under it")
set(common "\"size\":\"64x48\"")
set(good
"{\"scene\":\"builtin:default\",${common},\"backend\":\"cpu\",\"output\":\"out/cpu.png\"}
{\"scene\":\"builtin:default\",${common},\"backend\":\"gl\",\"output\":\"out/gl.png\",\"expected\":\"${GOLDEN}\",\"fail\":0.0079,\"failpercent\":1}
{\"scene\":\"builtin:default\",${common},\"set\":[\"shading=flat\"],\"backend\":\"cpu\",\"output\":\"out/flat.png\",\"expected\":\"${GOLDEN}\"}
{\"scene\":\"builtin:cube\",${common},\"settings\":{\"shading\":\"gouraud\"},\"backend\":\"gl\",\"output\":\"out/cube.png\"}
{\"scene\":\"builtin:sphere\",${common},\"backend\":\"ray\",\"output\":\"out/sphere.png\"}
{\"scene\":\"builtin:default\",${common},\"backend\":\"reference\",\"output\":\"out/reference.png\"}
")
file(WRITE ${DIR}/jobs.jsonl "# six good jobs, then bad ones\n${good}
{\"scene\":\"builtin:default\",${common},\"output\":\"out/bad.png\"
{\"scene\":\"builtin:default\",${common},\"output\":\"out/key.png\",\"colour\":\"red\"}
{\"scene\":\"no/such.glb\",${common},\"output\":\"out/missing.png\"}
{\"scene\":\"builtin:default\",${common},\"output\":\"blocker/x.png\"}
")
facet_run_command(COMMAND ${FACET} batch ${DIR}/jobs.jsonl --jobs 2 --junit ${DIR}/report.xml EXPECT 4)
foreach(name cpu gl flat cube sphere reference)
  if(NOT EXISTS ${DIR}/out/${name}.png)
    message(FATAL_ERROR "out/${name}.png was not written${report}")
  endif()
endforeach()
foreach(name bad key missing)
  if(EXISTS ${DIR}/out/${name}.png)
    message(FATAL_ERROR "out/${name}.png was written by a bad job${report}")
  endif()
endforeach()
foreach(pattern
    "line 3 [^\n]*out/gl.png PASS"
    "line 4 [^\n]*out/flat.png FAILURE"
    "line 9 - FILE ERROR [0-9]+ ms: [^\n]*jobs.jsonl:9: not JSON"
    "line 10 - FILE ERROR [0-9]+ ms: [^\n]*jobs.jsonl:10: unknown key 'colour'"
    "line 11 [^\n]*FILE ERROR [0-9]+ ms: [^\n]*jobs.jsonl:11: [^\n]*no/such.glb: no such file"
    "line 12 [^\n]*FILE ERROR [0-9]+ ms: [^\n]*jobs.jsonl:12: [^\n]*blocker/x.png: "
    "PASS +5\n" "FAILURE +1\n" "FILE ERROR +4\n" "10 jobs: 6 rendered, 0 skipped")
  if(NOT out MATCHES "${pattern}")
    message(FATAL_ERROR "stdout does not match '${pattern}'${report}")
  endif()
endforeach()
find_program(XMLLINT xmllint)
if(NOT XMLLINT)
  message(FATAL_ERROR "xmllint is not installed (Debian package libxml2-utils, scripts/install-deps.sh): cannot check report.xml")
endif()
execute_process(COMMAND ${XMLLINT} --noout ${DIR}/report.xml RESULT_VARIABLE xml_rc ERROR_VARIABLE xml_err)
if(NOT xml_rc EQUAL 0)
  message(FATAL_ERROR "report.xml is not well-formed XML: ${xml_err}")
endif()
# And as a JUnit consumer reads it (junitparser): counts and each case's result.
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/junit_consumer.py ${DIR}/report.xml 10 1 4 0
                        "line 3: ${DIR}/out/gl.png=passed" "line 4: ${DIR}/out/flat.png=failure" "line 9: (no output)=error"
                        "line 11: ${DIR}/out/missing.png=error"
                RESULT_VARIABLE junit_rc OUTPUT_VARIABLE junit_out ERROR_VARIABLE junit_err)
if(NOT junit_rc EQUAL 0)
  message(FATAL_ERROR "junitparser does not read report.xml as expected:\n${junit_out}${junit_err}")
endif()
file(READ ${DIR}/report.xml xml)
if(NOT xml MATCHES "<testsuite name=\"facet batch\" tests=\"10\" failures=\"1\" errors=\"4\" skipped=\"0\"")
  message(FATAL_ERROR "report.xml counts are wrong:\n${xml}")
endif()

# Without the bad lines: a comparison failing alone gives 2; then --resume.
file(WRITE ${DIR}/good.jsonl "${good}")
facet_run_command(COMMAND ${FACET} batch ${DIR}/good.jsonl EXPECT 2)
facet_run_command(COMMAND ${FACET} batch ${DIR}/good.jsonl --resume --junit ${DIR}/resumed.xml EXPECT 2)
if(NOT out MATCHES "6 jobs: 0 rendered, 6 skipped" OR NOT out MATCHES "line 3 [^\n]*out/flat.png FAILURE")
  message(FATAL_ERROR "--resume did not skip every job (and still compare)${report}")
endif()
string(REPLACE "shading=flat" "shading=phong" changed "${good}")
file(WRITE ${DIR}/good.jsonl "${changed}")
facet_run_command(COMMAND ${FACET} batch ${DIR}/good.jsonl --resume EXPECT 0)
if(NOT out MATCHES "6 jobs: 1 rendered, 5 skipped" OR NOT out MATCHES "line 3 [^\n]*out/flat.png PASS")
  message(FATAL_ERROR "--resume did not render the changed job again${report}")
endif()

# --resume sees the files a glTF names: a new texture renders the job again.
file(COPY ${ASSIMP}/BoxTextured-glTF/ DESTINATION ${DIR}/box)
file(WRITE ${DIR}/box.jsonl "{\"scene\":\"box/BoxTextured.gltf\",\"size\":\"32x32\",\"backend\":\"cpu\",\"output\":\"out/box.png\"}\n")
facet_run_command(COMMAND ${FACET} batch ${DIR}/box.jsonl --resume EXPECT 0)
facet_run_command(COMMAND ${FACET} batch ${DIR}/box.jsonl --resume EXPECT 0)
if(NOT out MATCHES "1 jobs?: 0 rendered, 1 skipped")
  message(FATAL_ERROR "--resume did not skip the unchanged textured job${report}")
endif()
# An output damaged after it was written (one byte of its IDAT flipped, the
# hash chunk intact) is rendered again, as facet diff would refuse to read it.
execute_process(COMMAND ${PYTHON} -c "import sys; p = sys.argv[1]; b = bytearray(open(p, 'rb').read()); i = b.find(b'IDAT') + 6; b[i] ^= 0xff; open(p, 'wb').write(b)"
                ${DIR}/out/box.png)
facet_run_command(COMMAND ${FACET} batch ${DIR}/box.jsonl --resume EXPECT 0)
if(NOT out MATCHES "1 jobs?: 1 rendered, 0 skipped")
  message(FATAL_ERROR "--resume kept an output whose image data is damaged${report}")
endif()
facet_run_command(COMMAND ${FACET} diff ${DIR}/out/box.png ${DIR}/out/box.png EXPECT 0)
file(COPY_FILE ${DIR}/out/cpu.png ${DIR}/box/CesiumLogoFlat.png)
facet_run_command(COMMAND ${FACET} batch ${DIR}/box.jsonl --resume EXPECT 0)
if(NOT out MATCHES "1 jobs?: 1 rendered, 0 skipped")
  message(FATAL_ERROR "--resume skipped a job whose texture changed${report}")
endif()

# The settings' file names (here a volume) are taken from the job file's
# folder too, and --resume sees their bytes, read once for the two jobs
# that share one: a change to it renders both again.
function(write_volume first)
  set(values "")
  foreach(k RANGE 63)
    math(EXPR v "(${k} * 4 + ${first}) % 256")
    string(APPEND values "${v} ")
  endforeach()
  file(WRITE ${DIR}/named/v.nrrd "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 4 4 4\nencoding: ascii\n\n${values}\n")
endfunction()
write_volume(0)
file(WRITE ${DIR}/named.jsonl
  "{\"scene\":\"builtin:cube\",\"set\":[\"volume.file=named/v.nrrd\"],\"size\":\"24x24\",\"backend\":\"cpu\",\"output\":\"out/named-1.png\"}\n"
  "{\"scene\":\"builtin:cube\",\"set\":[\"volume.file=named/v.nrrd\"],\"size\":\"24x24\",\"backend\":\"cpu\",\"output\":\"out/named-2.png\"}\n")
facet_run_command(COMMAND ${FACET} batch ${DIR}/named.jsonl --resume EXPECT 0)
facet_run_command(COMMAND ${FACET} batch ${DIR}/named.jsonl --resume EXPECT 0)
if(NOT out MATCHES "2 jobs: 0 rendered, 2 skipped")
  message(FATAL_ERROR "--resume did not skip the unchanged volume jobs${report}")
endif()
write_volume(1)
facet_run_command(COMMAND ${FACET} batch ${DIR}/named.jsonl --resume EXPECT 0)
if(NOT out MATCHES "2 jobs: 2 rendered, 0 skipped")
  message(FATAL_ERROR "--resume skipped jobs whose volume changed${report}")
endif()

# Shards of a 20-job file (with comments and an empty line between).
set(twenty "# twenty jobs\n")
foreach(k RANGE 1 20)
  string(APPEND twenty "{\"scene\":\"builtin:cube\",\"size\":\"16x16\",\"output\":\"shard/${k}.png\"}\n")
  if(k EQUAL 7)
    string(APPEND twenty "\n# a comment\n")
  endif()
endforeach()
file(WRITE ${DIR}/twenty.jsonl "${twenty}")
facet_run_command(COMMAND ${FACET} batch ${DIR}/twenty.jsonl --dry-run EXPECT 0)
set(all "${out}")
foreach(n 1 2 3 7)
  set(listed "")
  math(EXPR last "${n} - 1")
  foreach(i RANGE 0 ${last})
    facet_run_command(COMMAND ${FACET} batch ${DIR}/twenty.jsonl --dry-run --shard ${i}/${n} EXPECT 0)
    string(APPEND listed "${out}")
  endforeach()
  string(REGEX MATCHALL "[^\n]+" listed "${listed}")
  list(LENGTH listed count)
  list(REMOVE_DUPLICATES listed)
  list(LENGTH listed unique)
  string(REGEX MATCHALL "[^\n]+" everything "${all}")
  list(SORT listed)
  list(SORT everything)
  if(NOT count EQUAL 20 OR NOT unique EQUAL 20 OR NOT "${listed}" STREQUAL "${everything}")
    message(FATAL_ERROR "${n} shards do not list each of the 20 jobs once: ${count} lines, ${unique} different:\n${listed}")
  endif()
endforeach()
foreach(bad 0/0 5/3 a/b)
  facet_run_command(COMMAND ${FACET} batch ${DIR}/twenty.jsonl --shard ${bad} EXPECT 64)
  if(NOT err MATCHES "^facet: --shard '${bad}': ")
    message(FATAL_ERROR "--shard ${bad}: not one line naming it${report}")
  endif()
endforeach()

# Three shards' reports merged equal the whole run's, times apart.
facet_run_command(COMMAND ${FACET} batch ${DIR}/jobs.jsonl --junit ${DIR}/whole.xml EXPECT 4)
set(parts "")
foreach(i 0 1 2)
  facet_run_command(COMMAND ${FACET} batch ${DIR}/jobs.jsonl --shard ${i}/3 --junit ${DIR}/part${i}.xml EXPECT 4)
  list(APPEND parts ${DIR}/part${i}.xml)
endforeach()
facet_run_command(COMMAND ${FACET} batch --merge ${DIR}/merged.xml ${parts} EXPECT 0)
file(READ ${DIR}/whole.xml whole)
file(READ ${DIR}/merged.xml merged)
string(REGEX REPLACE " time=\"[0-9.]+\"" "" whole "${whole}")
string(REGEX REPLACE " time=\"[0-9.]+\"" "" merged "${merged}")
if(NOT whole STREQUAL merged)
  message(FATAL_ERROR "the merged shards' report differs from the whole run's:\n${whole}\n---\n${merged}")
endif()
message(STATUS "batch: bad jobs fail alone, resume skips, shards cover, reports merge")
