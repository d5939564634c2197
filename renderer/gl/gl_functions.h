#pragma once
// The OpenGL 4.5 core functions facet calls: glad 2's context struct
// (GladGLContext, generated at build time from Khronos' gl.xml by Debian's
// python3-glad, in its multi-context mode), filled through the getProcAddress
// of whatever context is current: OSMesa, EGL or GLFW. One struct per
// context, no global function pointers: facet may hold OSMesa and EGL
// contexts in one process, and their entry points need not be the same.
// Called as gl.ClipControl(...), glad's names: OpenGL's without "gl".
#include <string>

#include <glad/gl.h>

#include "gl/get_proc_address.h"

namespace facet::gl {

using GlFunctions = GladGLContext;

// Fills the struct through `getProcAddress` with a context current. Throws
// facet::Error when the context is older than OpenGL 4.5 or lacks one of
// its functions (getProcAddress of OSMesa and EGL returns stubs even for
// names a driver lacks, so the version is what proves support).
GlFunctions loadGlFunctions(const GetProcAddress& getProcAddress);

// GL_RENDERER and GL_VERSION: "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
std::string rendererAndVersion(const GlFunctions& gl);

// One glGetIntegerv value.
GLint getInteger(const GlFunctions& gl, GLenum name);

// Throws facet::Error "<who>OpenGL error 0x0502 in <where>" when the context
// has an error flag set, after clearing every flag.
void checkGlError(const GlFunctions& gl, const char* where, const std::string& who = "");

}  // namespace facet::gl
