#pragma once
// How the GL backend finds OpenGL functions: through the getProcAddress of
// whatever context is current (OSMesaGetProcAddress, eglGetProcAddress,
// glfwGetProcAddress). No OpenGL header is needed to name these types.
#include <functional>

namespace facet::gl {

using GlProc = void (*)();
using GetProcAddress = std::function<GlProc(const char* name)>;

}  // namespace facet::gl
