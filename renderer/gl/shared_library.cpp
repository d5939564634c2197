#include "gl/shared_library.h"

#include <cstdlib>

#include <dlfcn.h>

#include "common/error.h"

namespace facet::gl {

SharedLibrary::SharedLibrary(const std::string& soname, const char* overrideVariable, const std::string& purpose) {
  const char* override = std::getenv(overrideVariable);
  path_ = override && *override ? override : soname;
  // RTLD_NODELETE: Mesa and GLVND keep threads and thread-local state that
  // must not be unmapped while the process runs; dlclose only drops the handle.
  handle_ = dlopen(path_.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (!handle_) {
    const char* reason = dlerror();
    throw Error("cannot load " + path_ + ", needed for " + purpose + ": " + (reason ? reason : "dlopen failed") +
                (override ? std::string(" (set by ") + overrideVariable + ")" : std::string()));
  }
}

SharedLibrary::~SharedLibrary() { dlclose(handle_); }

void* SharedLibrary::address(const char* name) const {
  void* symbol = dlsym(handle_, name);
  if (!symbol) throw Error(path_ + " has no " + name);
  return symbol;
}

}  // namespace facet::gl
