#include "gl/headless_context.h"

#include "gl/driver_variables.h"

namespace facet::gl {

std::unique_ptr<HeadlessContext> makeHeadlessContext(GlContextKind kind) {
  checkDriverVariables();
  return kind == GlContextKind::Egl ? makeEglContext() : makeOsMesaContext();
}

}  // namespace facet::gl
