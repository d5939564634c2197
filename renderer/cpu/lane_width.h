#pragma once
// How many pixels the CPU backend's Phong lighting takes at a time: 8 where
// the CPU has AVX2 (and facet was built with its eight-lane code: x86-64),
// else 4 with SSE2, else 1. Each width gives the same bits (lanes.h); the
// eight-lane code lives in the translation units built for AVX2
// (*_avx2.cpp), chosen at run time, so one build runs on any x86-64.

namespace facet::cpu {

// The widest this CPU runs.
int widestLanes();

// Throws facet::Error unless `lanes` is 1, 4 or 8 and at most widestLanes().
void checkLanes(int lanes);

}  // namespace facet::cpu
