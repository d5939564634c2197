#pragma once
// A shader stage's source as the driver gets it. GLSL has no #include, so the
// stage file's `#include "file"` lines are replaced by those files (each file
// once per stage, in the order met), with #line directives around them so the
// driver counts lines per file. Its messages name a file by its GLSL
// source-string number; describeLog turns those back into file names.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facet::gl {

struct ShaderSource {
  std::string text;
  std::vector<std::string> files;  // files[n]: the file of source-string number n; files[0] is the stage file
};

// Text of a shader file by name, or nullopt when there is none.
using ShaderFileLookup = std::function<std::optional<std::string_view>(std::string_view name)>;

// The embedded shaders/ files.
std::optional<std::string_view> findEmbeddedShaderFile(std::string_view name);

// Throws facet::Error naming the file that is missing or malformed.
ShaderSource assembleShaderSource(std::string_view stageFile, const ShaderFileLookup& find = findEmbeddedShaderFile);

// A driver's info log on one line ("; " between its lines), with Mesa's
// "N:L(C)" prefixes written as "file:L(C)".
std::string describeLog(std::string_view log, const std::vector<std::string>& files);

}  // namespace facet::gl
