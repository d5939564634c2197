#pragma once
// An OpenGL 4.5 core context with no window, for `facet render` and the
// tests: OSMesa (libOSMesa.so.8) or EGL surfaceless (libEGL.so.1), both on
// Mesa's llvmpipe here. A context only creates, makes current and finds
// functions; drawing is GlFrameRenderer's, which the viewer reuses with a
// GLFW window's context instead of one of these.
#include <memory>
#include <string_view>

#include "gl/get_proc_address.h"
#include "gl/gl_renderer.h"

namespace facet::gl {

class HeadlessContext {
 public:
  virtual ~HeadlessContext() = default;
  // Makes this context current on the calling thread; throws facet::Error.
  virtual void makeCurrent() = 0;
  virtual GlProc getProcAddress(const char* name) const = 0;
  // "osmesa" or "egl", as --context spells it.
  virtual std::string_view name() const = 0;
};

// Loads the library, creates the context and makes it current. Throws
// facet::Error naming the library or the call that failed.
std::unique_ptr<HeadlessContext> makeHeadlessContext(GlContextKind kind);

// The two kinds, defined in osmesa_context.cpp and egl_context.cpp.
std::unique_ptr<HeadlessContext> makeOsMesaContext();
std::unique_ptr<HeadlessContext> makeEglContext();

}  // namespace facet::gl
