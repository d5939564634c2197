#pragma once
// A shared library opened at run time (dlopen) rather than linked, so that a
// machine without it gets one facet::Error naming the library and the Debian
// package to install, instead of a loader failure before main.
#include <string>

namespace facet::gl {

class SharedLibrary {
 public:
  // Opens `soname`, or the file the environment variable `overrideVariable`
  // names when it is set (tests use it to provoke a missing library).
  // `purpose` completes the error message: "OSMesa (Debian package libosmesa6)".
  SharedLibrary(const std::string& soname, const char* overrideVariable, const std::string& purpose);
  ~SharedLibrary();
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  // The symbol `name` as a function pointer of type F; throws facet::Error when absent.
  template <typename F>
  F function(const char* name) const {
    return reinterpret_cast<F>(address(name));
  }

  const std::string& path() const { return path_; }

 private:
  void* address(const char* name) const;

  std::string path_;
  void* handle_ = nullptr;
};

}  // namespace facet::gl
