#pragma once
// Triangle setup and coverage as llvmpipe does it (Mesa 22.3,
// src/gallium/drivers/llvmpipe/lp_setup_tri.c: calc_fixed_position,
// do_triangle_ccw; lp_rast.h: FIXED_ORDER), read from the source and checked
// against llvmpipe on 10^5 random triangles with zero differing pixels:
//
// - Vertices snap to a 1/256-pixel grid: X = round_half_even((x_w - 0.5)·256)
//   (cvtps2dq in the default rounding mode). The grid origin is a pixel centre,
//   so pixel (px, py) sits at (256·px, 256·py).
// - The fixed-point signed area decides everything: 0 drops the triangle;
//   positive is counter-clockwise in GL's window coordinates (front-facing).
// - Edge i -> j of the triangle ordered clockwise: dcdx = Y_i - Y_j,
//   dcdy = X_i - X_j, c = dcdx·X_i - dcdy·Y_i, plus 1 for a left edge
//   (dcdx < 0) or a horizontal bottom edge (dcdx = 0, dcdy > 0). A pixel is
//   covered when c - dcdx·256·px + dcdy·256·py > 0 on all three edges, so a
//   centre on a left or bottom edge is in, on a right or top edge out, and a
//   shared edge is covered exactly once.
#include <cstdint>

#include "cpu/clipper.h"

namespace facet::cpu {

struct EdgeFunction {
  std::int64_t c = 0, dcdx = 0, dcdy = 0;
  std::int64_t at(int px, int py) const { return c - dcdx * 256 * px + dcdy * 256 * py; }
};

struct TriangleSetup {
  EdgeFunction edges[3];
  bool frontFacing = true;     // counter-clockwise in window coordinates
  int minX = 0, maxX = -1;     // pixel bounding box, clamped to the target
  int minY = 0, maxY = -1;
};

// x_w to the 1/256 grid, pixel centre at 0.
std::int32_t snapToGrid(float windowCoordinate);

// Returns false when the snapped triangle has zero area or no pixel of the
// target's [0,width)×[0,height) in its bounding box.
bool setupTriangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, int width, int height, TriangleSetup& out);

}  // namespace facet::cpu
