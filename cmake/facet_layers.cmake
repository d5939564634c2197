# The layers of renderer/: one library per folder, each linking only the
# folders below it (renderer/CMakeLists.txt declares them bottom up). The
# build enforces the order: before a layer compiles, check_layer_includes.cmake
# reads every #include "folder/..." of its files and stops the build at one
# that names a folder the layer does not link (directly or through the
# layers below), so a back arrow fails the build, not a review.
set(FACET_LAYER_CHECK ${CMAKE_CURRENT_LIST_DIR}/check_layer_includes.cmake)
set_property(GLOBAL PROPERTY FACET_LAYERS "")
set_property(GLOBAL PROPERTY FACET_LAYERS_NOT_BUILT "")

# facet_layer(FOLDER [DEPENDS lower folders...] [SOURCES files...])
# Declares the library facet_FOLDER over renderer/FOLDER (STATIC with
# sources, INTERFACE without), links the layers it DEPENDS on publicly, and
# records what it may include: itself and everything its DEPENDS may.
function(facet_layer folder)
  cmake_parse_arguments(PARSE_ARGV 1 LAYER "" "" "DEPENDS;SOURCES")
  set(allowed ${folder})
  set(linked)
  foreach(dep IN LISTS LAYER_DEPENDS)
    get_property(known GLOBAL PROPERTY FACET_LAYERS)
    if(NOT dep IN_LIST known)
      message(FATAL_ERROR "layer ${folder} depends on ${dep}, which is not declared below it")
    endif()
    get_property(below GLOBAL PROPERTY FACET_LAYER_ALLOWED_${dep})
    list(APPEND allowed ${below})
    list(APPEND linked facet_${dep})
  endforeach()
  list(REMOVE_DUPLICATES allowed)
  set_property(GLOBAL PROPERTY FACET_LAYER_ALLOWED_${folder} ${allowed})
  set_property(GLOBAL APPEND PROPERTY FACET_LAYERS ${folder})

  if(LAYER_SOURCES)
    add_library(facet_${folder} STATIC ${LAYER_SOURCES})
    target_include_directories(facet_${folder} PUBLIC ${PROJECT_SOURCE_DIR}/renderer)
    target_link_libraries(facet_${folder} PUBLIC ${linked} PRIVATE facet_warnings facet_fp)
    if(FACET_SANITIZE)
      target_link_libraries(facet_${folder} PUBLIC facet_sanitize)
    endif()
    set(scope PUBLIC)
  else()
    add_library(facet_${folder} INTERFACE)
    target_include_directories(facet_${folder} INTERFACE ${PROJECT_SOURCE_DIR}/renderer)
    target_link_libraries(facet_${folder} INTERFACE ${linked})
  endif()

  # The include check, re-run whenever a file of the folder changes.
  file(GLOB_RECURSE files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/renderer/${folder}/*.h ${PROJECT_SOURCE_DIR}/renderer/${folder}/*.cpp)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${folder}_layer.checked)
  facet_renderer_folders(folders)
  string(JOIN "," allowed_text ${allowed})
  string(JOIN "," folders_text ${folders})
  add_custom_command(OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -DLAYER=${folder} -DALLOWED=${allowed_text} -DLAYERS=${folders_text}
            -DROOT=${PROJECT_SOURCE_DIR}/renderer -DSTAMP=${stamp} -P ${FACET_LAYER_CHECK}
    DEPENDS ${files} ${FACET_LAYER_CHECK}
    COMMENT "Checking that renderer/${folder} includes only the layers below it"
    VERBATIM)
  add_custom_target(facet_${folder}_layer_check DEPENDS ${stamp})
  add_dependencies(facet_${folder} facet_${folder}_layer_check)
endfunction()

# The folders of renderer/: every one is a layer (facet_layers_done), and
# an include of "folder/..." names a layer when folder is one of them.
function(facet_renderer_folders out)
  file(GLOB entries LIST_DIRECTORIES true RELATIVE ${PROJECT_SOURCE_DIR}/renderer ${PROJECT_SOURCE_DIR}/renderer/*)
  set(folders)
  foreach(entry IN LISTS entries)
    if(IS_DIRECTORY ${PROJECT_SOURCE_DIR}/renderer/${entry})
      list(APPEND folders ${entry})
    endif()
  endforeach()
  set(${out} ${folders} PARENT_SCOPE)
endfunction()

# facet_layer_not_built(FOLDER): a layer this configuration leaves out
# (gl with FACET_BUILD_GL=OFF); facet_layers_done accepts its folder.
function(facet_layer_not_built folder)
  set_property(GLOBAL APPEND PROPERTY FACET_LAYERS_NOT_BUILT ${folder})
endfunction()

# After the last facet_layer(): a folder of renderer/ that is not a layer is refused.
function(facet_layers_done)
  get_property(built GLOBAL PROPERTY FACET_LAYERS)
  get_property(not_built GLOBAL PROPERTY FACET_LAYERS_NOT_BUILT)
  set(layers ${built} ${not_built})
  facet_renderer_folders(folders)
  foreach(folder IN LISTS folders)
    if(NOT folder IN_LIST layers)
      message(FATAL_ERROR "renderer/${folder} is not a layer: declare it with facet_layer() in renderer/CMakeLists.txt")
    endif()
  endforeach()
endfunction()
