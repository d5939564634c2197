#include "gl/gl_functions.h"

#include <cstdio>

#include "common/error.h"

namespace facet::gl {

GlFunctions loadGlFunctions(const GetProcAddress& getProcAddress) {
  GlFunctions gl;
  // Casting from void(*)() to the function's own type is the one pointer cast
  // every GL loader makes; the pointer was typed that way by the driver.
#define FACET_GL_LOAD(type, name)                                                          \
  gl.name = reinterpret_cast<type>(getProcAddress(#name));                                 \
  if (!gl.name) throw Error("OpenGL: the context has no " #name " (facet needs OpenGL 4.5 core)");
  FACET_GL_FUNCTIONS(FACET_GL_LOAD)
#undef FACET_GL_LOAD

  const GLint major = getInteger(gl, GL_MAJOR_VERSION), minor = getInteger(gl, GL_MINOR_VERSION);
  if (major * 10 + minor < 45)
    throw Error("OpenGL: facet needs OpenGL 4.5 core, the context gives " + std::to_string(major) + "." + std::to_string(minor) + " (" +
                rendererAndVersion(gl) + ")");
  return gl;
}

std::string rendererAndVersion(const GlFunctions& gl) {
  const auto text = [&](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(gl.glGetString(name));
    return std::string(s ? s : "?");
  };
  return text(GL_RENDERER) + ", " + text(GL_VERSION);
}

void checkGlError(const GlFunctions& gl, const char* where, const std::string& who) {
  const GLenum error = gl.glGetError();
  if (error == GL_NO_ERROR) return;
  while (gl.glGetError() != GL_NO_ERROR) {
  }
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", error);
  throw Error(who + "OpenGL error " + code + " in " + where);
}

GLint getInteger(const GlFunctions& gl, GLenum name) {
  GLint value = 0;
  gl.glGetIntegerv(name, &value);
  return value;
}

}  // namespace facet::gl
