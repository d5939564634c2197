#include "cpu/triangle_setup.h"

#include <algorithm>
#include <cmath>

namespace facet::cpu {

std::int32_t snapToGrid(float windowCoordinate) {
  // (x - 0.5)·256 is exact in float for |x| < 2^22; nearbyint rounds half to even.
  return static_cast<std::int32_t>(std::nearbyint((windowCoordinate - 0.5f) * 256.0f));
}

bool setupTriangle(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, int width, int height, TriangleSetup& out) {
  // After clipping, window coordinates lie within the viewport (no guard band)
  // — unless w is so near 0 that 1/w overflowed while |x| ≤ w still held.
  // Such a triangle has no sensible pixels; dropping it also keeps the
  // conversion to fixed point defined. (The comparison is false for NaN.)
  constexpr float kLimit = 1 << 22;
  for (const WindowVertex* v : {&a, &b, &c})
    if (!(std::fabs(v->x) < kLimit && std::fabs(v->y) < kLimit)) return false;
  std::int64_t X[3] = {snapToGrid(a.x), snapToGrid(b.x), snapToGrid(c.x)};
  std::int64_t Y[3] = {snapToGrid(a.y), snapToGrid(b.y), snapToGrid(c.y)};
  // llvmpipe's area: positive for clockwise in GL window coordinates.
  const std::int64_t area = (X[0] - X[1]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[0] - Y[1]);
  if (area == 0) return false;
  out.frontFacing = area < 0;
  if (area < 0) {  // reorder to llvmpipe's canonical (clockwise) orientation
    std::swap(X[0], X[1]);
    std::swap(Y[0], Y[1]);
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    EdgeFunction& e = out.edges[i];
    e.dcdx = Y[i] - Y[j];
    e.dcdy = X[i] - X[j];
    e.c = e.dcdx * X[i] - e.dcdy * Y[i];
    if (e.dcdx < 0 || (e.dcdx == 0 && e.dcdy > 0)) e.c += 1;  // left or bottom edge: inclusive
  }
  // Pixel centres 256·px inside [min X, max X]: px from ceil(minX/256) to floor(maxX/256).
  const std::int64_t minX = std::min({X[0], X[1], X[2]}), maxX = std::max({X[0], X[1], X[2]});
  const std::int64_t minY = std::min({Y[0], Y[1], Y[2]}), maxY = std::max({Y[0], Y[1], Y[2]});
  out.minX = static_cast<int>(std::max<std::int64_t>(0, (minX + 255) >> 8));
  out.maxX = static_cast<int>(std::min<std::int64_t>(width - 1, maxX >> 8));
  out.minY = static_cast<int>(std::max<std::int64_t>(0, (minY + 255) >> 8));
  out.maxY = static_cast<int>(std::min<std::int64_t>(height - 1, maxY >> 8));
  return out.minX <= out.maxX && out.minY <= out.maxY;
}

}  // namespace facet::cpu
