# The AVX2 objects (renderer/cpu/*_avx2.cpp) may define no function another
# object could also define: the linker keeps one copy of an inline function
# or template instance for the whole program, and an AVX2 copy of a shared
# one would run on CPUs without AVX2. Allowed: each file's entry point and
# instances of the eight-lane types, which no other object has. Data (the
# series' constants) is the same bytes whichever copy is kept.
#   cmake -DNM=nm "-DOBJECTS=a.o;b.o" -P avx2_symbols.cmake
cmake_policy(SET CMP0057 NEW)  # if(... IN_LIST ...)
set(entries "shadeEightLanes")
set(found "")
foreach(object IN LISTS OBJECTS)
  execute_process(COMMAND ${NM} -C --defined-only --extern-only -f sysv ${object} RESULT_VARIABLE rc OUTPUT_VARIABLE symbols ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "nm ${object}: ${err}")
  endif()
  string(REPLACE "\n" ";" lines "${symbols}")
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "[|] *FUNC *[|]")  # sysv format: name|value|class|type|size|line|section
      continue()
    endif()
    if(line MATCHES "^facet::cpu::([A-Za-z]+)[(]" AND CMAKE_MATCH_1 IN_LIST entries)
      list(APPEND found ${CMAKE_MATCH_1})
    elseif(NOT line MATCHES "Float8|Vec3x8|Mask8|Int8")
      message(FATAL_ERROR "${object} defines a function other objects may define too, and the linker may keep its AVX2 copy:\n  ${line}")
    endif()
  endforeach()
endforeach()
foreach(entry IN LISTS entries)
  if(NOT entry IN_LIST found)
    message(FATAL_ERROR "no AVX2 object defines facet::cpu::${entry}")
  endif()
endforeach()
