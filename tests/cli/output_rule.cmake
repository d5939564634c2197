# One output rule for render and info: no output is a file the command reads
# (the glTF, its buffers and images, whatever the spelling), and no two
# outputs are one file, even on the first run when neither exists yet
# (-o and --shadow-report, -o and --write-isosurface; through ./, an
# absolute name or a link). Each refusal is one line, exit 1, and leaves
# every file as it was. Run with -DFACET=... -DDIR=... -DBOX=(BoxTextured-glTF folder)
include(${CMAKE_CURRENT_LIST_DIR}/../run_command.cmake)
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
file(COPY ${BOX}/ DESTINATION ${DIR}/box)
file(CREATE_LINK ${DIR} ${DIR}/link SYMBOLIC)
file(SHA256 ${DIR}/box/BoxTextured0.bin bin_before)
file(SHA256 ${DIR}/box/CesiumLogoFlat.png png_before)

function(refused pattern)
  facet_run_command(COMMAND ${ARGN} WORKING_DIRECTORY ${DIR} EXPECT 1)
  string(STRIP "${err}" text)
  if(NOT text MATCHES "${pattern}" OR text MATCHES "\n")
    message(FATAL_ERROR "expected one line matching ${pattern}${report}")
  endif()
endfunction()
set(render ${FACET} render --backend cpu --size 32x32)

refused("^facet: box/BoxTextured0.bin: is the input .*box/BoxTextured0.bin under another name" ${render} box/BoxTextured.gltf -o box/BoxTextured0.bin)
refused("^facet: box/CesiumLogoFlat.png: is the input .*CesiumLogoFlat.png under another name" ${render} box/BoxTextured.gltf -o box/CesiumLogoFlat.png)
refused("^facet: box/BoxTextured.gltf: is an input of this command" ${render} box/BoxTextured.gltf -o box/BoxTextured.gltf)
file(SHA256 ${DIR}/box/BoxTextured0.bin bin_after)
file(SHA256 ${DIR}/box/CesiumLogoFlat.png png_after)
if(NOT bin_before STREQUAL bin_after OR NOT png_before STREQUAL png_after)
  message(FATAL_ERROR "a refused render changed the scene's files")
endif()

refused("^facet: x.png: named twice as an output of this command \\(-o and --shadow-report\\)" ${render} -o x.png --shadow-report x.png)
refused("^facet: ./x.png: named twice as an output of this command \\(-o and --shadow-report\\)" ${render} -o x.png --shadow-report ./x.png)
refused("^facet: ${DIR}/x.png: named twice" ${render} -o link/x.png --shadow-report ${DIR}/x.png)
refused("^facet: f0.png: named twice as an output of this command \\(-o and --shadow-report\\)" ${render} --turntable 2 -o f{frame}.png --shadow-report f{n}.png)
refused("^facet: ./iso.gltf: named twice as an output of this command \\(-o and --write-isosurface\\)"
  ${FACET} info builtin:marschner-lobb --set volume.mode=isosurface --set volume.resolution=8 -o iso.gltf --write-isosurface ./iso.gltf)
file(GLOB written ${DIR}/*.png ${DIR}/*.gltf)
if(written)
  message(FATAL_ERROR "a refused command wrote ${written}")
endif()

# Distinct outputs beside the scene's files are written.
facet_run_command(COMMAND ${render} box/BoxTextured.gltf -o box/render.png --shadow-report box/shadows.png WORKING_DIRECTORY ${DIR} EXPECT 0)
if(NOT EXISTS ${DIR}/box/render.png OR NOT EXISTS ${DIR}/box/shadows.png)
  message(FATAL_ERROR "distinct outputs were not written${report}")
endif()
# batch: a job's output is never the job file nor a file of its scene; two
# jobs' outputs and a job's expected image are compared as files, not as
# spellings; --junit is none of the jobs' files. The bad jobs fail alone (4).
file(WRITE ${DIR}/jobs.jsonl
"{\"scene\":\"builtin:cube\",\"size\":\"16x16\",\"backend\":\"cpu\",\"output\":\"jobs.jsonl\"}
{\"scene\":\"box/BoxTextured.gltf\",\"size\":\"16x16\",\"backend\":\"cpu\",\"output\":\"box/BoxTextured0.bin\"}
{\"scene\":\"builtin:cube\",\"size\":\"16x16\",\"backend\":\"cpu\",\"output\":\"out/a.png\"}
{\"scene\":\"builtin:cube\",\"size\":\"16x16\",\"backend\":\"cpu\",\"output\":\"${DIR}/out/a.png\"}
{\"scene\":\"builtin:cube\",\"size\":\"16x16\",\"backend\":\"cpu\",\"output\":\"out/b.png\",\"expected\":\"link/out/b.png\"}
")
file(SHA256 ${DIR}/jobs.jsonl jobs_before)
facet_run_command(COMMAND ${FACET} batch jobs.jsonl WORKING_DIRECTORY ${DIR} EXPECT 4)
foreach(pattern "line 1 [^\n]*FILE ERROR[^\n]*jobs.jsonl: is an input of this command"
                "line 2 [^\n]*FILE ERROR[^\n]*BoxTextured0.bin: is the input [^\n]*BoxTextured0.bin under another name"
                "line 3 [^\n]*PASS"
                "line 4 [^\n]*FILE ERROR[^\n]*output [^\n]*out/a.png is written by line 3 already"
                "line 5 [^\n]*FILE ERROR[^\n]*expected [^\n]*link/out/b.png is this job's own output")
  if(NOT out MATCHES "${pattern}")
    message(FATAL_ERROR "batch: expected a line matching ${pattern}${report}")
  endif()
endforeach()
file(SHA256 ${DIR}/jobs.jsonl jobs_after)
file(SHA256 ${DIR}/box/BoxTextured0.bin bin_after)
if(NOT jobs_before STREQUAL jobs_after OR NOT bin_before STREQUAL bin_after)
  message(FATAL_ERROR "batch replaced its job file or a scene's buffer")
endif()
file(WRITE ${DIR}/golden.jsonl "{\"scene\":\"builtin:cube\",\"size\":\"16x16\",\"backend\":\"cpu\",\"output\":\"out/c.png\",\"expected\":\"out/a.png\"}\n")
file(SHA256 ${DIR}/out/a.png golden_before)
facet_run_command(COMMAND ${FACET} batch golden.jsonl --junit ./out/a.png WORKING_DIRECTORY ${DIR} EXPECT 4)
file(SHA256 ${DIR}/out/a.png golden_after)
if(NOT err MATCHES "out/a.png: is the input" OR NOT golden_before STREQUAL golden_after OR EXISTS ${DIR}/out/c.png)
  message(FATAL_ERROR "batch --junit may replace the golden a job compares against${report}")
endif()
message(STATUS "outputs: never an input, never twice")
