#pragma once
// Runs this very binary (or another) as a child process: what `facet bench`
// times the first PNG and measures peak memory with, and what `facet view
// --bench-orbit` measures a headless frame with, each in a fresh process.
#include <string>
#include <vector>

namespace facet {

// Runs args (args[0] a path) to completion, stdout captured into `out` when
// given (else sent to /dev/null); returns the exit status (128: killed).
// With `peakKilobytes`, stores the child's peak resident memory, the
// kernel's ru_maxrss from wait4 (KB). On Linux that figure is never below
// this process's own peak at the spawn: the child runs in this process's
// memory until its exec (posix_spawn), and exec keeps the high-water mark of
// the memory it leaves. So a caller that wants the child's own figure spawns
// it before it grows itself.
// Throws facet::Error when it cannot start.
int runChild(const std::vector<std::string>& args, std::string* out, long* peakKilobytes = nullptr);

// The running binary's path (/proc/self/exe).
std::string selfPath();

}  // namespace facet
