# cmake -DLAYER=folder -DALLOWED=a,b,... -DLAYERS=every,layer -DROOT=renderer [-DSTAMP=file] -P check_layer_includes.cmake
# Fails (naming the file, the line and the include) when a file of
# ROOT/LAYER includes "X/..." for a layer X outside ALLOWED: an arrow from a
# lower layer up. Writes STAMP when every include is allowed.
cmake_minimum_required(VERSION 3.25)
string(REPLACE "," ";" ALLOWED "${ALLOWED}")
string(REPLACE "," ";" LAYERS "${LAYERS}")
file(GLOB_RECURSE files ${ROOT}/${LAYER}/*.h ${ROOT}/${LAYER}/*.cpp)
set(problems "")
foreach(file IN LISTS files)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"/]+/")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"/]+)/.*$" "\\1" folder "${line}")
    if(folder IN_LIST LAYERS AND NOT folder IN_LIST ALLOWED)
      file(RELATIVE_PATH shown ${ROOT}/.. ${file})
      string(STRIP "${line}" line)
      string(JOIN ", " allowed_text ${ALLOWED})
      string(APPEND problems "  ${shown}: ${line}: ${LAYER} may include only ${allowed_text}\n")
    endif()
  endforeach()
endforeach()
if(problems)
  # Indented, so that CMake prints each line whole.
  message(FATAL_ERROR "An include from a lower layer up (the order: renderer/CMakeLists.txt):\n${problems}")
endif()
if(STAMP)
  file(TOUCH ${STAMP})
endif()
