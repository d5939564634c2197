# Run at build time (cmake -P): writes OUTPUT, a C++ source that defines
# facet::gl::embeddedShaderFiles() with every file of SHADERS (a list of
# paths) as a raw string literal, so that facet needs no shaders/ folder at
# run time. #include lines stay as they are; gl/shader_source.cpp expands them.
set(delimiter "glsl")
set(content "// Generated from shaders/ by renderer/gl/embed_shaders.cmake; do not edit.\n")
string(APPEND content "#include \"gl/embedded_shaders.h\"\n\nnamespace facet::gl {\nnamespace {\n\n")
string(APPEND content "constexpr ShaderFile kFiles[] = {\n")
foreach(path IN LISTS SHADERS)
  get_filename_component(name "${path}" NAME)
  file(READ "${path}" text)
  string(FIND "${text}" ")${delimiter}\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${path} contains )${delimiter}\" and cannot be embedded as a raw string literal")
  endif()
  string(APPEND content "    {\"${name}\", R\"${delimiter}(${text})${delimiter}\"},\n")
endforeach()
string(APPEND content "};\n\n}  // namespace\n\n")
string(APPEND content "std::span<const ShaderFile> embeddedShaderFiles() { return kFiles; }\n\n}  // namespace facet::gl\n")

# Rewrite only on change, so that an untouched shader set does not rebuild facet_gl.
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" previous)
  if(previous STREQUAL content)
    return()
  endif()
endif()
file(WRITE "${OUTPUT}" "${content}")
