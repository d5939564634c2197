#include "frame_setup.h"

#include "common/error.h"
#include "cpu/cpu_renderer.h"
#include "cpu/reference/reference_renderer.h"
#if FACET_HAVE_GL
#include "gl/gl_renderer.h"
#endif

namespace facet {

std::unique_ptr<Renderer> makeBackend(const std::string& backend, const std::string& context, int threads, RenderProgress progress) {
  if (backend == "cpu") return makeCpuRenderer(threads);
  if (backend == "reference") return makeReferenceRenderer();
  if (backend == "ray") return makeRayRenderer(threads, std::move(progress));
#if FACET_HAVE_GL
  GlContextKind kind = GlContextKind::OsMesa;
  if (context == "egl") kind = GlContextKind::Egl;
  else if (context != "osmesa") throw Error("--context '" + context + "': expected osmesa or egl");
  return makeGlRenderer(kind);
#else
  (void)context;
  throw Error("--backend gl: this build has no OpenGL backend (configured with FACET_BUILD_GL=OFF)");
#endif
}

}  // namespace facet
