// How facet ends on an exception that no command turned into a result
// (app/exit_status.h): one line on stderr and one exit code per kind, and
// none of a bad input's codes (1, 64) for what is not the input's fault.
#include <cstdio>
#include <new>
#include <stdexcept>
#include <string>

#include <doctest/doctest.h>

#include "common/error.h"
#include "exit_status.h"

using namespace facet;

namespace {

struct Reported {
  int exitCode;
  std::string line;
};

Reported report(std::exception_ptr error) {
  std::FILE* out = std::tmpfile();
  REQUIRE(out);
  const int code = reportError(error, out);
  std::rewind(out);
  std::string text;
  for (int c; (c = std::fgetc(out)) != EOF;) text += static_cast<char>(c);
  std::fclose(out);
  return {code, text};
}

template <class E>
Reported report(const E& e) {
  return report(std::make_exception_ptr(e));
}

}  // namespace

TEST_CASE("exit status: bad input exits 1, a wrong command line 64, each with its message") {
  const Reported bad = report(Error("scene.gltf: no such file"));
  CHECK(bad.exitCode == 1);
  CHECK(bad.line == "facet: scene.gltf: no such file\n");
  const Reported usage = report(UsageError("--size '0x5': each side must be in [1, 16384]"));
  CHECK(usage.exitCode == 64);
  CHECK(usage.line == "facet: --size '0x5': each side must be in [1, 16384]\n");
}

TEST_CASE("exit status: out of memory and every other exception exit 70, on one line") {
  const Reported named = report(OutOfMemory("decoding big.png (16384x16384)"));
  CHECK(named.exitCode == 70);
  CHECK(named.line == "facet: out of memory while decoding big.png (16384x16384)\n");
  const Reported plain = report(std::bad_alloc());
  CHECK(plain.exitCode == 70);
  CHECK(plain.line == "facet: out of memory\n");
  const Reported internal = report(std::out_of_range("vector::_M_range_check:\n__n (which is 7)"));
  CHECK(internal.exitCode == 70);
  CHECK(internal.line == "facet: internal error: vector::_M_range_check: __n (which is 7)\n");
  const Reported unknown = report(std::make_exception_ptr(42));
  CHECK(unknown.exitCode == 70);
  CHECK(unknown.line == "facet: internal error: an exception that is not a std::exception\n");
  CHECK(kExitInternal == 70);
}

TEST_CASE("exit status: a message of any length stays one line") {
  const Reported longOne = report(std::runtime_error(std::string(5000, 'x')));
  CHECK(longOne.line == "facet: internal error: " + std::string(1000, 'x') + "...\n");
}
