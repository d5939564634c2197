#include "gl/gl_functions.h"

#include <cstdio>

#include "common/error.h"

namespace facet::gl {

GlFunctions loadGlFunctions(const GetProcAddress& getProcAddress) {
  GlFunctions gl{};
  // glad hands the name back with our std::function as its user pointer.
  const auto load = [](void* user, const char* name) -> GLADapiproc { return (*static_cast<const GetProcAddress*>(user))(name); };
  const int version = gladLoadGLContextUserPtr(&gl, load, const_cast<GetProcAddress*>(&getProcAddress));
  if (version == 0 || gl.GetString == nullptr || gl.GetIntegerv == nullptr)
    throw Error("OpenGL: the context gives no version (facet needs OpenGL 4.5 core)");
  if (!gl.VERSION_4_5)
    throw Error("OpenGL: facet needs OpenGL 4.5 core, the context gives " + std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                std::to_string(GLAD_VERSION_MINOR(version)) + " (" + rendererAndVersion(gl) + ")");
  // A driver that claims 4.5 but leaves a 4.5 entry point out: glad loads
  // what the driver gives, so the newest ones facet calls are checked.
  if (gl.ClipControl == nullptr || gl.CreateTextures == nullptr || gl.GetTextureSubImage == nullptr)
    throw Error("OpenGL: the context claims 4.5 but lacks its direct-state-access functions (" + rendererAndVersion(gl) + ")");
  return gl;
}

std::string rendererAndVersion(const GlFunctions& gl) {
  const auto text = [&](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(gl.GetString(name));
    return std::string(s ? s : "?");
  };
  return text(GL_RENDERER) + ", " + text(GL_VERSION);
}

void checkGlError(const GlFunctions& gl, const char* where, const std::string& who) {
  const GLenum error = gl.GetError();
  if (error == GL_NO_ERROR) return;
  while (gl.GetError() != GL_NO_ERROR) {
  }
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", error);
  throw Error(who + "OpenGL error " + code + " in " + where);
}

GLint getInteger(const GlFunctions& gl, GLenum name) {
  GLint value = 0;
  gl.GetIntegerv(name, &value);
  return value;
}

}  // namespace facet::gl
