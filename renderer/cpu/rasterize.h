#pragma once
// The plain per-pixel walk: every pixel of the box whose centre passes the
// three edge tests of triangle_setup.h, in row order. The reference that the
// renderer's block-first coverage (tile_raster.h) is tested against
// (tests/cpu/test_coverage.cpp). A template, so the fragment stage inlines
// into the loop with no virtual call per pixel.
#include "cpu/triangle_setup.h"

namespace facet::cpu {

template <class Fragment>
void rasterize(const SnappedTriangle& t, const PixelBox& box, Fragment&& fragment) {
  EdgeFunction e[3];
  edgeFunctions(t, e);
  for (int py = box.minY; py <= box.maxY; ++py)
    for (int px = box.minX; px <= box.maxX; ++px)
      if (e[0].at(px, py) > 0 && e[1].at(px, py) > 0 && e[2].at(px, py) > 0) fragment(px, py);
}

}  // namespace facet::cpu
