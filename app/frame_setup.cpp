#include "frame_setup.h"

#include "common/error.h"
#include "cpu/cpu_renderer.h"
#include "cpu/reference/reference_renderer.h"
#if FACET_HAVE_GL
#include "gl/gl_renderer.h"
#endif

namespace facet {

namespace {

// --context auto: EGL surfaceless first (Mesa 25.1 and later have no
// OSMesa), OSMesa where EGL cannot start. When neither loads, one line says
// why each did not and what renders without a driver.
std::unique_ptr<Renderer> makeGlBackend(const std::string& context) {
#if FACET_HAVE_GL
  if (context == "egl") return makeGlRenderer(GlContextKind::Egl);
  if (context == "osmesa") return makeGlRenderer(GlContextKind::OsMesa);
  if (context != "auto") throw Error("--context '" + context + "': expected auto, egl or osmesa");
  std::string egl;
  try {
    return makeGlRenderer(GlContextKind::Egl);
  } catch (const Error& e) {
    egl = e.what();
  }
  try {
    return makeGlRenderer(GlContextKind::OsMesa);
  } catch (const Error& e) {
    throw Error("--backend gl: no OpenGL driver loads (EGL: " + egl + "; OSMesa: " + e.what() + "); --backend cpu renders without one");
  }
#else
  (void)context;
  throw Error("--backend gl: this build has no OpenGL backend (configured with FACET_BUILD_GL=OFF); --backend cpu renders without one");
#endif
}

}  // namespace

std::unique_ptr<Renderer> makeBackend(const std::string& backend, const std::string& context, int threads, RenderProgress progress) {
  if (backend == "cpu") return makeCpuRenderer(threads);
  if (backend == "reference") return makeReferenceRenderer();
  if (backend == "ray") return makeRayRenderer(threads, std::move(progress));
  if (backend == "auto") {
    try {
      return makeGlBackend(context);
    } catch (const Error&) {
      return makeCpuRenderer(threads);  // no driver loads: the CPU rasterizer draws the same image
    }
  }
  return makeGlBackend(context);
}

void refuseUndrawnImage(const std::string& backend, const FrameInputs& frame) {
  if (backend == "reference") refuseReferenceImage(frame);
  if (backend == "ray") refuseRayImage(frame);
#if FACET_HAVE_GL
  if (backend == "gl") refuseCpuOnlyFrame(frame);
#endif
}

}  // namespace facet
