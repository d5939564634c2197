#include "gl/driver_variables.h"

#include <cstdlib>
#include <string>

#include "common/error.h"
#include "common/quote.h"

namespace facet::gl {

void checkDriverVariables() {
  // Mesa's software drivers: softpipe stops at OpenGL 3.3, zink and the
  // others need a device; an unknown or empty name crashes libOSMesa.
  const char* driver = std::getenv("GALLIUM_DRIVER");
  if (driver != nullptr && std::string(driver) != "llvmpipe")
    throw Error("GALLIUM_DRIVER=" + quoteInput(driver) +
                ": the OpenGL backend runs on Mesa's llvmpipe; unset GALLIUM_DRIVER or set it to llvmpipe");
}

}  // namespace facet::gl
