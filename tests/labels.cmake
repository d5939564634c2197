# Labels. Every ctest entry carries one tier and at least one area:
#   quick   a minute or so of test time on two cores: `ctest -L quick`
#           while working; scripts/sanitize.sh runs it whole
#   long    everything else: scripts/test.sh (and CI's release run) runs
#           both tiers, scripts/sanitize.sh a rotating shard of this one
#   areas   what an entry tests (FACET_AREAS): `ctest -L ray`
# A directory names its area and its long entries once, at the top of its
# CMakeLists.txt:
#   facet_labels(AREA area... | FOLDERS folder...  [LONG regex...])
# and the labels go on every entry it declares, when it has declared them
# all: long when the entry's name matches one of the regular expressions,
# quick otherwise. An entry may carry more areas, or its tier, set where it
# is declared.
# Doctest executables are declared with facet_doctest (doctest_discover_tests
# plus their labels). labels.every_entry_has_a_tier_and_an_area fails when
# an entry has no tier, two, or no area.
set(FACET_TIERS quick long)
set(FACET_AREAS agreement batch cli common compare cpu docs fuzz gl image layers math packaging particles pipeline ray robustness scene settings suite
                viewer volume)

# facet_doctest(TARGET [PREFIX prefix]): its cases as ctest entries, named
# PREFIX + the case's name, each labelled by the directory's facet_labels;
# one that skipped a check this host cannot run is reported as skipped
# (tests/skipped.h).
function(facet_doctest target)
  cmake_parse_arguments(PARSE_ARGV 1 T "" "PREFIX" "")
  doctest_discover_tests(${target} TEST_PREFIX "${T_PREFIX}" PROPERTIES SKIP_RETURN_CODE 77)
  set_property(DIRECTORY APPEND PROPERTY FACET_DOCTESTS ${target})
  set_property(TARGET ${target} PROPERTY FACET_TEST_PREFIX "${T_PREFIX}")
endfunction()

function(facet_labels)
  # Deferred to the end of the directory (even one that returns early), with
  # the arguments as given here.
  set(arguments)
  foreach(argument IN LISTS ARGN)
    string(APPEND arguments " [==[${argument}]==]")
  endforeach()
  cmake_language(EVAL CODE "cmake_language(DEFER CALL facet_label_directory ${arguments})")
endfunction()

function(facet_label_directory)
  cmake_parse_arguments(PARSE_ARGV 0 T "" "" "AREA;FOLDERS;LONG")
  list(JOIN T_LONG "|" long_regex)
  # The entries of add_test, now.
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(test IN LISTS tests)
    get_property(labels TEST ${test} PROPERTY LABELS)
    set(tier quick)
    if("quick" IN_LIST labels OR "long" IN_LIST labels)
      set(tier)  # set where the entry is declared
    elseif(T_LONG AND test MATCHES "${long_regex}")
      set(tier long)
    endif()
    set_property(TEST ${test} APPEND PROPERTY LABELS ${tier} ${T_AREA})
  endforeach()
  # A doctest executable's cases are known once it is built: ctest labels
  # them (doctest_labels.cmake) after it reads doctest's list of them. With
  # FOLDERS, a case's area is the folder of tests/ its source file is in, as
  # the executable itself says after each build (doctest_folders.cmake).
  get_property(targets DIRECTORY PROPERTY FACET_DOCTESTS)
  foreach(target IN LISTS targets)
    set(script ${CMAKE_CURRENT_BINARY_DIR}/${target}_labels.cmake)
    set(text "set(facet_target ${target})\nset(facet_long [==[${long_regex}]==])\nset(facet_areas ${T_AREA})\nset(facet_folders ${T_FOLDERS})\n")
    if(T_FOLDERS)
      get_property(prefix TARGET ${target} PROPERTY FACET_TEST_PREFIX)
      list(JOIN T_FOLDERS "," folders)  # one argument of the command
      set(cases ${CMAKE_CURRENT_BINARY_DIR}/${target}_folders.cmake)
      add_custom_command(TARGET ${target} POST_BUILD
        COMMAND ${CMAKE_COMMAND} -DEXECUTABLE=$<TARGET_FILE:${target}> -DTARGET=${target} "-DPREFIX=${prefix}" -DFOLDERS=${folders}
                -DOUT=${cases} -P ${PROJECT_SOURCE_DIR}/tests/doctest_folders.cmake
        VERBATIM)
      string(APPEND text "include([==[${cases}]==] OPTIONAL)\n")
    endif()
    string(APPEND text "include([==[${PROJECT_SOURCE_DIR}/tests/doctest_labels.cmake]==])\n")
    file(WRITE ${script} "${text}")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${script})
  endforeach()
endfunction()
