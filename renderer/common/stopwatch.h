#pragma once
// Elapsed wall time for the printed timings (passes, start-up, benches).
#include <chrono>

namespace facet {

// Milliseconds from `start` to now on the steady clock, which never jumps.
double millisecondsSince(std::chrono::steady_clock::time_point start);

}  // namespace facet
