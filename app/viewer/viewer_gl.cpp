#include "viewer/viewer_gl.h"

#include "common/error.h"

namespace facet::viewer {

ViewerGl loadViewerGl(const gl::GetProcAddress& getProcAddress) {
  ViewerGl functions{gl::loadGlFunctions(getProcAddress), nullptr};  // checks the version first
  // The one pointer cast every GL loader makes: the driver typed the function this way.
  functions.glBlitNamedFramebuffer = reinterpret_cast<PFNGLBLITNAMEDFRAMEBUFFERPROC>(getProcAddress("glBlitNamedFramebuffer"));
  if (!functions.glBlitNamedFramebuffer) throw Error("OpenGL: the context has no glBlitNamedFramebuffer (facet needs OpenGL 4.5 core)");
  return functions;
}

}  // namespace facet::viewer
