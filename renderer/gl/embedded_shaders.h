#pragma once
// The files of shaders/, compiled into the binary (embed_shaders.cmake
// generates the definition at build time), so facet runs from any directory.
#include <span>
#include <string_view>

namespace facet::gl {

struct ShaderFile {
  std::string_view name;  // file name in shaders/, e.g. "lighting.glsl"
  std::string_view text;
};

std::span<const ShaderFile> embeddedShaderFiles();

}  // namespace facet::gl
