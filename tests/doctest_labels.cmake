# Read by ctest, after doctest's list of a doctest executable's cases: the
# labels of each case (tests/labels.cmake). Set before: facet_target, the
# executable; facet_long, the regular expression of its long cases (empty:
# none); facet_areas, its area, or facet_folders, the folders of tests/
# whose names are its cases' areas, with ${facet_target}_IN_FOLDER listing
# the cases of each (doctest_folders.cmake).
foreach(test IN LISTS ${facet_target}_TESTS)
  set(labels quick)
  if(facet_long AND test MATCHES "${facet_long}")
    set(labels long)
  endif()
  list(APPEND labels ${facet_areas})
  foreach(folder IN LISTS facet_folders)
    list(FIND ${facet_target}_IN_${folder} "${test}" at)  # not IN_LIST: ctest reads this file under CMake's oldest policies
    if(at GREATER -1)
      list(APPEND labels ${folder})
    endif()
  endforeach()
  set_tests_properties("${test}" PROPERTIES LABELS "${labels}")
endforeach()
