#pragma once
// How facet ends: the exit codes every command shares, and the one line on
// stderr for an exception that no command turned into a result.
#include <cstdio>
#include <exception>

namespace facet {

inline constexpr int kExitBadInput = 1;   // a bad file, a frame that cannot be drawn (facet::Error)
inline constexpr int kExitUsage = 64;     // EX_USAGE: the command line itself is wrong (facet::UsageError)
inline constexpr int kExitInternal = 70;  // EX_SOFTWARE: out of memory, or a bug: not the input's fault

// Prints one line for `error` to `out`, "facet: <message>", and returns its
// exit code: UsageError 64, Error 1; std::bad_alloc ("out of memory", with
// what facet was doing for an OutOfMemory) and every other exception
// ("internal error: ...") 70.
int reportError(std::exception_ptr error, std::FILE* out);

// Writes "facet: " prefix text suffix and a newline as one line: control
// bytes in `text` become spaces, and it is cut after 1000 bytes
// (a message facet did not write, such as CLI11's or a library's, may hold
// anything). Allocates nothing: it also runs when memory has run out.
void printErrorLine(std::FILE* out, const char* prefix, const char* text, const char* suffix = "");

}  // namespace facet
