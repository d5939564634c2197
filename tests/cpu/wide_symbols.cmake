# The wide objects (renderer/cpu/*_avx2.cpp, *_avx512.cpp, renderer/shading/resolve_avx512.cpp) may define no
# function another object could also define: the linker keeps one copy of
# an inline function or template instance for the whole program, and an
# AVX2 or AVX-512 copy of a shared one would run on CPUs without it.
# Allowed: the object's entry point and instances of its own lane types,
# which no other object has (an AVX-512 object's eight-lane instance would
# not be allowed: the AVX2 object has them too). Data (the series'
# constants) is the same bytes whichever copy is kept.
#   cmake -DNM=nm "-DOBJECTS=a.o;b.o" "-DENTRIES=shadeSixteenLanes;resolveSixteenLanes" "-DTYPES=Float16|Vec3x16|Mask16|Int16" -P wide_symbols.cmake
cmake_policy(SET CMP0057 NEW)  # if(... IN_LIST ...)
set(found)
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
    if(line MATCHES "^facet::(cpu::)?([A-Za-z]+)[(]" AND CMAKE_MATCH_2 IN_LIST ENTRIES)
      list(APPEND found ${CMAKE_MATCH_2})
    elseif(NOT line MATCHES "${TYPES}")
      message(FATAL_ERROR "${object} defines a function other objects may define too, and the linker may keep its wide copy:\n  ${line}")
    endif()
  endforeach()
endforeach()
foreach(entry IN LISTS ENTRIES)
  if(NOT entry IN_LIST found)
    message(FATAL_ERROR "no object of ${OBJECTS} defines facet::cpu::${entry}")
  endif()
endforeach()
