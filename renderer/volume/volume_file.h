#pragma once
// What the volume readers share: the check that a path is a file before a
// library opens it, and a sample type as messages name it.
#include <cstddef>
#include <string>

namespace facet {

// Throws facet::Error "<shown>: no such file" or "not a regular file" (or
// the system's reason), before a reader hands `path` to its library.
void requireRegularFile(const std::string& path, const std::string& shown);

// A file's sample type: how messages name it, its bytes, and whether facet reads it.
struct SampleType {
  const char* name = "";  // as messages say it: "int16", "float64"
  std::size_t bytes = 0;
  bool supported = false;
};

}  // namespace facet
