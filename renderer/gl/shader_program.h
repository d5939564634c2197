#pragma once
// A linked GLSL program built from shader stage files. The stage is the
// file's extension: .vert, .frag (and .geom, .comp if ever needed).
#include <initializer_list>
#include <string>
#include <string_view>

#include "gl/gl_object.h"
#include "gl/shader_source.h"

namespace facet::gl {

class ShaderProgram {
 public:
  ShaderProgram(GlObject program, std::string name) : program_(std::move(program)), name_(std::move(name)) {}

  GLuint id() const { return program_.id(); }
  const std::string& name() const { return name_; }  // "lit_phong.vert + lit_phong.frag"

 private:
  GlObject program_;
  std::string name_;
};

// Compiles each stage file and links them. `defines` (#define lines) go
// right after each stage's #version line; line numbers in the driver's
// messages still count from the file's own first line. Throws facet::Error
// naming the file (compile) or the program (link), with the driver's log on
// the same line.
ShaderProgram buildProgram(const GlFunctions& gl, std::initializer_list<std::string_view> stageFiles, std::string_view defines = {},
                           const ShaderFileLookup& find = findEmbeddedShaderFile);

// glGetUniformLocation; -1 (a uniform the compiler removed) is legal for glProgramUniform*, which then does nothing.
GLint uniformLocation(const GlFunctions& gl, const ShaderProgram& program, const char* name);

}  // namespace facet::gl
