// EGL surfaceless (EGL_MESA_platform_surfaceless): an OpenGL context with no
// display server and no GPU device. libEGL.so.1 (GLVND) is loaded with dlopen;
// <EGL/egl.h> is included for its types only.
#define EGL_EGL_PROTOTYPES 0
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "common/error.h"
#include "gl/headless_context.h"
#include "gl/shared_library.h"

namespace facet::gl {
namespace {

bool hasExtension(const char* extensions, const char* name) {
  if (!extensions) return false;
  const std::size_t length = std::strlen(name);
  for (const char* p = std::strstr(extensions, name); p; p = std::strstr(p + length, name))
    if ((p == extensions || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0')) return true;
  return false;
}

std::string hex(EGLint code) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%04x", static_cast<unsigned>(code));
  return text;
}

class EglContext final : public HeadlessContext {
 public:
  EglContext()
      : library_("libEGL.so.1", "FACET_EGL_LIBRARY", "EGL, the headless OpenGL context (Debian packages libegl1 and libegl-mesa0)"),
        getProcAddress_(library_.function<PFNEGLGETPROCADDRESSPROC>("eglGetProcAddress")),
        getError_(library_.function<PFNEGLGETERRORPROC>("eglGetError")),
        makeCurrent_(library_.function<PFNEGLMAKECURRENTPROC>("eglMakeCurrent")),
        destroyContext_(library_.function<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext")),
        releaseThread_(library_.function<PFNEGLRELEASETHREADPROC>("eglReleaseThread")) {
    const auto queryString = library_.function<PFNEGLQUERYSTRINGPROC>("eglQueryString");
    if (!hasExtension(queryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless"))
      throw Error("egl: " + library_.path() + " lacks EGL_MESA_platform_surfaceless (is Mesa's libegl-mesa0 installed?)");
    // eglGetDisplay(EGL_DEFAULT_DISPLAY) fails without a display server; the platform must be named.
    display_ = library_.function<PFNEGLGETPLATFORMDISPLAYPROC>("eglGetPlatformDisplay")(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                                                                     nullptr);
    if (display_ == EGL_NO_DISPLAY) fail("eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA)");
    if (!library_.function<PFNEGLINITIALIZEPROC>("eglInitialize")(display_, nullptr, nullptr)) fail("eglInitialize");
    const char* displayExtensions = queryString(display_, EGL_EXTENSIONS);
    for (const char* needed : {"EGL_KHR_no_config_context", "EGL_KHR_surfaceless_context"})
      if (!hasExtension(displayExtensions, needed)) throw Error(std::string("egl: the surfaceless display lacks ") + needed);
    if (!library_.function<PFNEGLBINDAPIPROC>("eglBindAPI")(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API)");
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = library_.function<PFNEGLCREATECONTEXTPROC>("eglCreateContext")(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT) fail("eglCreateContext (OpenGL 4.5 core)");
    try {
      makeCurrent();
    } catch (...) {
      destroyContext_(display_, context_);
      throw;
    }
  }

  // The display is not terminated: every EglContext of the process shares the
  // one surfaceless display, and eglTerminate would pull it from under the others.
  ~EglContext() override {
    makeCurrent_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    destroyContext_(display_, context_);
    releaseThread_();
  }

  void makeCurrent() override {
    if (!makeCurrent_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail("eglMakeCurrent");
  }

  GlProc getProcAddress(const char* name) const override { return getProcAddress_(name); }
  std::string_view name() const override { return "egl"; }

 private:
  [[noreturn]] void fail(const std::string& call) const { throw Error("egl: " + call + " failed with EGL error " + hex(getError_())); }

  SharedLibrary library_;
  PFNEGLGETPROCADDRESSPROC getProcAddress_;
  PFNEGLGETERRORPROC getError_;
  PFNEGLMAKECURRENTPROC makeCurrent_;
  PFNEGLDESTROYCONTEXTPROC destroyContext_;
  PFNEGLRELEASETHREADPROC releaseThread_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<HeadlessContext> makeEglContext() { return std::make_unique<EglContext>(); }

}  // namespace facet::gl
