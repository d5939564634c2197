#include "gl/headless_context.h"

namespace facet::gl {

std::unique_ptr<HeadlessContext> makeHeadlessContext(GlContextKind kind) {
  return kind == GlContextKind::Egl ? makeEglContext() : makeOsMesaContext();
}

}  // namespace facet::gl
