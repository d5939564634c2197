#pragma once
// One error type for bad input anywhere in facet. Its message is the single
// line a user sees: it names the file (or settings key) and the problem.
#include <new>
#include <stdexcept>
#include <string>

namespace facet {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// Bad input on the command line itself (a --set key or value, a --size):
// the command exits 64 (EX_USAGE) instead of 1.
class UsageError : public Error {
 public:
  using Error::Error;
};

// Memory ran out while working on a named input. Not bad input: like every
// std::bad_alloc it ends facet with exit code 70, but its line says what
// was being done ("out of memory while decoding big.png (16384x16384)").
class OutOfMemory : public std::bad_alloc {
 public:
  explicit OutOfMemory(const std::string& doing) : doing_(doing) {}
  const char* what() const noexcept override { return doing_.what(); }

 private:
  std::runtime_error doing_;  // "decoding big.png (16384x16384)"; copies without allocating
};

}  // namespace facet
