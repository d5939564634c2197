#pragma once
// The OpenGL functions the viewer calls itself, beside what GlFrameRenderer
// draws: the GL backend's table (textures, read-back, clears) plus the blit
// that copies the renderer's framebuffer to the window.
#include "gl/gl_functions.h"

namespace facet::viewer {

struct ViewerGl {
  gl::GlFunctions gl;  // facet_gl's table, loaded from the window's context
  PFNGLBLITNAMEDFRAMEBUFFERPROC glBlitNamedFramebuffer = nullptr;
};

// With the window's context current. Throws facet::Error without OpenGL 4.5 core.
ViewerGl loadViewerGl(const gl::GetProcAddress& getProcAddress);

}  // namespace facet::viewer
