#pragma once
// A check this host cannot run (a lane width its CPU lacks), said so and
// counted, so that it shows as skipped rather than passed: a test case that
// skipped one ends with exit code kSkippedExitCode when it passes
// (test_main.cpp), and ctest reports that as skipped (SKIP_RETURN_CODE,
// tests/labels.cmake). A run of many cases at once prints the messages and
// exits 0.
#include <string>

namespace facet::test {

inline constexpr int kSkippedExitCode = 77;  // Automake's, which ctest's SKIP_RETURN_CODE is set to

// A doctest MESSAGE "skipped: WHAT", and the current test case counted as skipped.
void skipped(const std::string& what);

}  // namespace facet::test
