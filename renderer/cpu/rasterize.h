#pragma once
// The plain per-pixel walk over a set-up triangle's bounding box, rows [rowBegin, rowEnd):
// the reference that tests/cpu/test_coverage.cpp holds the renderer's tiled,
// block-first coverage (tile_raster.h) against. Walks the pixels it covers,
// calling fragment(px, py) for each, in row order. A template, so the
// fragment stage inlines into the loop with no virtual call per pixel.
#include <algorithm>

#include "cpu/triangle_setup.h"

namespace facet::cpu {

template <class Fragment>
void rasterize(const TriangleSetup& t, int rowBegin, int rowEnd, Fragment&& fragment) {
  const int y0 = std::max(t.minY, rowBegin), y1 = std::min(t.maxY, rowEnd - 1);
  const EdgeFunction& e0 = t.edges[0];
  const EdgeFunction& e1 = t.edges[1];
  const EdgeFunction& e2 = t.edges[2];
  for (int py = y0; py <= y1; ++py) {
    // Edge values at the row's first pixel, then stepped by -dcdx·256 per pixel.
    std::int64_t w0 = e0.at(t.minX, py), w1 = e1.at(t.minX, py), w2 = e2.at(t.minX, py);
    const std::int64_t s0 = e0.dcdx * 256, s1 = e1.dcdx * 256, s2 = e2.dcdx * 256;
    for (int px = t.minX; px <= t.maxX; ++px) {
      if (w0 > 0 && w1 > 0 && w2 > 0) fragment(px, py);
      w0 -= s0;
      w1 -= s1;
      w2 -= s2;
    }
  }
}

}  // namespace facet::cpu
