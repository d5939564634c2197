#include "gl/shader_program.h"

#include <algorithm>
#include <vector>

#include "common/error.h"
#include "settings/render_settings.h"

namespace facet::gl {
namespace {

GLenum stageOf(std::string_view file) {
  const std::string_view extension = file.substr(std::min(file.rfind('.'), file.size()));
  if (extension == ".vert") return GL_VERTEX_SHADER;
  if (extension == ".geom") return GL_GEOMETRY_SHADER;
  if (extension == ".frag") return GL_FRAGMENT_SHADER;
  if (extension == ".comp") return GL_COMPUTE_SHADER;
  throw Error("shader " + std::string(file) + ": unknown stage (expected .vert, .geom, .frag or .comp)");
}

std::string infoLog(const GlFunctions& gl, GLuint object, bool program) {
  GLint length = 0;
  (program ? gl.GetProgramiv : gl.GetShaderiv)(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  (program ? gl.GetProgramInfoLog : gl.GetShaderInfoLog)(object, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return log;
}

// The stage's text with `defines` after its first line (#version), and a
// #line directive that puts the second line back at line 2 of source string 0.
std::string withDefines(const std::string& text, std::string_view defines) {
  if (defines.empty()) return text;
  const std::size_t firstLineEnd = text.find('\n');
  if (firstLineEnd == std::string::npos || text.rfind("#version", 0) != 0) return std::string(defines) + text;
  return text.substr(0, firstLineEnd + 1) + std::string(defines) + "#line 2 0\n" + text.substr(firstLineEnd + 1);
}

// What every program is compiled with: the limits the C++ side holds (render_settings.h).
std::string commonDefines() { return "#define FACET_MAX_LIGHTS " + std::to_string(kMaxLights) + "\n"; }

GlObject compileStage(const GlFunctions& gl, std::string_view file, std::string_view defines, const ShaderFileLookup& find) {
  ShaderSource source = assembleShaderSource(file, find);
  source.text = withDefines(source.text, commonDefines() + std::string(defines));
  GlObject shader(gl, gl.CreateShader(stageOf(file)), [](const GlFunctions& f, GLuint id) { f.DeleteShader(id); });
  const char* text = source.text.c_str();
  const auto length = static_cast<GLint>(source.text.size());
  gl.ShaderSource(shader.id(), 1, &text, &length);
  gl.CompileShader(shader.id());
  GLint compiled = GL_FALSE;
  gl.GetShaderiv(shader.id(), GL_COMPILE_STATUS, &compiled);
  if (!compiled) throw Error("shader " + std::string(file) + " does not compile: " + describeLog(infoLog(gl, shader.id(), false), source.files));
  return shader;
}

}  // namespace

ShaderProgram buildProgram(const GlFunctions& gl, std::initializer_list<std::string_view> stageFiles, std::string_view defines,
                           const ShaderFileLookup& find) {
  std::string name;
  std::vector<GlObject> shaders;
  for (std::string_view file : stageFiles) {
    name += (name.empty() ? "" : " + ") + std::string(file);
    shaders.push_back(compileStage(gl, file, defines, find));
  }
  GlObject program(gl, gl.CreateProgram(), [](const GlFunctions& f, GLuint id) { f.DeleteProgram(id); });
  for (const GlObject& shader : shaders) gl.AttachShader(program.id(), shader.id());
  gl.LinkProgram(program.id());
  GLint linked = GL_FALSE;
  gl.GetProgramiv(program.id(), GL_LINK_STATUS, &linked);
  if (!linked) throw Error("shader program " + name + " does not link: " + describeLog(infoLog(gl, program.id(), true), {}));
  return {std::move(program), name};  // the shaders are deleted here; the program keeps them while it lives
}

GLint uniformLocation(const GlFunctions& gl, const ShaderProgram& program, const char* name) {
  return gl.GetUniformLocation(program.id(), name);
}

}  // namespace facet::gl
