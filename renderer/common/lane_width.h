#pragma once
// How many pixels the CPU backend's Phong lighting takes at a time: 16
// where the CPU has AVX-512F, 8 where it has AVX2 (and facet was built with
// that code: x86-64), else 4 with SSE2, else 1. Each width gives the same
// bits (lanes.h); the wide code lives in translation units built for their
// instruction sets (*_avx2.cpp, *_avx512.cpp), chosen at run time, so one
// build runs on any x86-64.

namespace facet {

// The widest this CPU runs.
int widestLanes();

// Throws facet::Error unless `lanes` is 1, 4, 8 or 16 and at most widestLanes().
void checkLanes(int lanes);

}  // namespace facet
