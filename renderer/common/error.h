#pragma once
// One error type for bad input anywhere in facet. Its message is the single
// line a user sees: it names the file (or settings key) and the problem.
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

}  // namespace facet
