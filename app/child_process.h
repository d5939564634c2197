#pragma once
// Runs this very binary (or another) as a child process: what `facet bench`
// times the first PNG and peak memory with, and what `facet view
// --bench-orbit` measures a headless frame with, each in a fresh process.
#include <string>
#include <vector>

namespace facet {

// Runs args (args[0] a path) to completion, stdout captured into `out` when
// given (else sent to /dev/null); returns the exit status (128: killed).
// Throws facet::Error when it cannot start.
int runChild(const std::vector<std::string>& args, std::string* out);

// The running binary's path (/proc/self/exe).
std::string selfPath();

}  // namespace facet
