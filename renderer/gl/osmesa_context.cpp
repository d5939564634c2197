// OSMesa: Mesa's off-screen context, loaded with dlopen (libOSMesa.so.8).
// This file includes <GL/osmesa.h> (and with it <GL/gl.h>) only for the
// declarations' types; every call goes through pointers from dlsym.
#include <GL/osmesa.h>

#include <array>

#include "common/error.h"
#include "gl/headless_context.h"
#include "gl/shared_library.h"

namespace facet::gl {
namespace {

class OsMesaContext final : public HeadlessContext {
 public:
  OsMesaContext()
      : library_("libOSMesa.so.8", "FACET_OSMESA_LIBRARY", "OSMesa, the headless OpenGL context (Debian package libosmesa6)"),
        createContextAttribs_(library_.function<decltype(&OSMesaCreateContextAttribs)>("OSMesaCreateContextAttribs")),
        makeCurrent_(library_.function<decltype(&OSMesaMakeCurrent)>("OSMesaMakeCurrent")),
        destroyContext_(library_.function<decltype(&OSMesaDestroyContext)>("OSMesaDestroyContext")),
        getProcAddress_(library_.function<decltype(&OSMesaGetProcAddress)>("OSMesaGetProcAddress")) {
    // No depth or stencil in OSMesa's own buffer: facet draws into framebuffer objects.
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4,
                              OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    context_ = createContextAttribs_(attributes, nullptr);
    if (!context_)
      throw Error("osmesa: OSMesaCreateContextAttribs could not create an OpenGL 4.5 core context with " + library_.path() +
                  " (is MESA_GL_VERSION_OVERRIDE or GALLIUM_DRIVER set?)");
    try {
      makeCurrent();
    } catch (...) {
      destroyContext_(context_);
      throw;
    }
  }

  ~OsMesaContext() override { destroyContext_(context_); }

  void makeCurrent() override {
    // OSMesaMakeCurrent refuses a null buffer; 1x1 is enough since nothing is drawn into it.
    if (!makeCurrent_(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) throw Error("osmesa: OSMesaMakeCurrent failed");
  }

  GlProc getProcAddress(const char* name) const override { return getProcAddress_(name); }
  std::string_view name() const override { return "osmesa"; }

 private:
  SharedLibrary library_;
  decltype(&OSMesaCreateContextAttribs) createContextAttribs_;
  decltype(&OSMesaMakeCurrent) makeCurrent_;
  decltype(&OSMesaDestroyContext) destroyContext_;
  decltype(&OSMesaGetProcAddress) getProcAddress_;
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> buffer_{};  // the 1x1 RGBA colour buffer OSMesa needs, alive as long as the context
};

}  // namespace

std::unique_ptr<HeadlessContext> makeOsMesaContext() { return std::make_unique<OsMesaContext>(); }

}  // namespace facet::gl
