#pragma once
// Triangle set-up and coverage as llvmpipe does it (Mesa 22.3,
// src/gallium/drivers/llvmpipe/lp_setup_tri.c: calc_fixed_position,
// triangle_both / do_triangle_ccw; lp_rast.h: FIXED_ORDER), read from the
// source and checked against llvmpipe on 10^5 random triangles with zero
// differing pixels (renderer/PIPELINE.md, "Rasterization"):
//
// - Vertices snap to a 1/256-pixel grid: X = round_half_even((x_w - 0.5)·256)
//   (cvtps2dq in the default rounding mode). The grid origin is a pixel centre,
//   so pixel (px, py) sits at (256·px, 256·py).
// - The fixed-point signed area decides everything: 0 drops the triangle;
//   negative is counter-clockwise in GL's window coordinates (front-facing),
//   and llvmpipe then swaps the first two vertices, for its edges and for its
//   interpolation set-up alike (plane_equations.h): that is the set-up order.
// - Edge i -> j of the triangle in set-up order: dcdx = Y_i - Y_j,
//   dcdy = X_i - X_j, c = dcdx·X_i - dcdy·Y_i, plus 1 for a left edge
//   (dcdx < 0) or a horizontal bottom edge (dcdx = 0, dcdy > 0). A pixel is
//   covered when c - dcdx·256·px + dcdy·256·py > 0 on all three edges, so a
//   centre on a left or bottom edge is in, on a right or top edge out, and a
//   shared edge is covered exactly once.
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace facet::cpu {

// x_w to the 1/256 grid, pixel centre at 0. (x - 0.5)·256 is exact in float
// for |x| < 2^22; nearbyint rounds half to even.
inline std::int32_t snapToGrid(float windowCoordinate) {
  return static_cast<std::int32_t>(std::nearbyint((windowCoordinate - 0.5f) * 256.0f));
}

// A triangle on the grid, in set-up order.
struct SnappedTriangle {
  std::int32_t X[3]{}, Y[3]{};  // 1/256 pixel, pixel centres at multiples of 256
  bool frontFacing = false;  // counter-clockwise in window coordinates; the first two vertices were swapped
};

// Pixels, inclusive.
struct PixelBox {
  int minX = 0, minY = 0, maxX = -1, maxY = -1;
};

// Snaps the triangle with window coordinates (x, y) of its vertices a, b, c
// in submitted order. False when its area is 0 on the grid, or when a
// coordinate is not below 2^22 in magnitude (w so near 0 that 1/w
// overflowed while |x| ≤ w held; such a triangle has no sensible pixels, and
// dropping it keeps the conversion to fixed point defined; NaN too).
inline bool snapTriangle(const float (&x)[3], const float (&y)[3], SnappedTriangle& out) {
  constexpr float kLimit = 1 << 22;
  for (int i = 0; i < 3; ++i)
    if (!(std::fabs(x[i]) < kLimit && std::fabs(y[i]) < kLimit)) return false;
  for (int i = 0; i < 3; ++i) out.X[i] = snapToGrid(x[i]), out.Y[i] = snapToGrid(y[i]);
  const std::int64_t X0 = out.X[0], X1 = out.X[1], X2 = out.X[2], Y0 = out.Y[0], Y1 = out.Y[1], Y2 = out.Y[2];
  // llvmpipe's area: (x0 - x1)·(y2 - y0) - (x2 - x0)·(y0 - y1), positive for clockwise.
  const std::int64_t area = (X0 - X1) * (Y2 - Y0) - (X2 - X0) * (Y0 - Y1);
  if (area == 0) return false;
  out.frontFacing = area < 0;
  if (out.frontFacing) {
    std::swap(out.X[0], out.X[1]);
    std::swap(out.Y[0], out.Y[1]);
  }
  return true;
}

// Puts a triangle's three vertices (anything) into set-up order.
template <class T>
void toSetUpOrder(const SnappedTriangle& t, T (&vertices)[3]) {
  if (t.frontFacing) std::swap(vertices[0], vertices[1]);
}

// The pixels whose centres lie inside the triangle's grid bounding box,
// within [x0, x1]×[y0, y1]: px from ceil(min X/256) to floor(max X/256).
// False when there are none.
inline bool pixelBox(const SnappedTriangle& t, int x0, int y0, int x1, int y1, PixelBox& box) {
  const std::int64_t lx = std::min({t.X[0], t.X[1], t.X[2]}), hx = std::max({t.X[0], t.X[1], t.X[2]});
  const std::int64_t ly = std::min({t.Y[0], t.Y[1], t.Y[2]}), hy = std::max({t.Y[0], t.Y[1], t.Y[2]});
  box.minX = static_cast<int>(std::max<std::int64_t>(x0, (lx + 255) >> 8));
  box.maxX = static_cast<int>(std::min<std::int64_t>(x1, hx >> 8));
  box.minY = static_cast<int>(std::max<std::int64_t>(y0, (ly + 255) >> 8));
  box.maxY = static_cast<int>(std::min<std::int64_t>(y1, hy >> 8));
  return box.minX <= box.maxX && box.minY <= box.maxY;
}

// Edge i -> i+1: covered when at(px, py) > 0 for all three.
struct EdgeFunction {
  std::int64_t c = 0, dcdx = 0, dcdy = 0;
  std::int64_t at(int px, int py) const { return c - dcdx * 256 * px + dcdy * 256 * py; }
};

inline void edgeFunctions(const SnappedTriangle& t, EdgeFunction (&edges)[3]) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    EdgeFunction& e = edges[i];
    e.dcdx = std::int64_t{t.Y[i]} - t.Y[j];
    e.dcdy = std::int64_t{t.X[i]} - t.X[j];
    e.c = e.dcdx * t.X[i] - e.dcdy * t.Y[i];
    if (e.dcdx < 0 || (e.dcdx == 0 && e.dcdy > 0)) e.c += 1;  // left or bottom edge: inclusive
  }
}

}  // namespace facet::cpu
