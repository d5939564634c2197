#include "cpu/line_raster.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace facet::cpu {
namespace {

constexpr float kGridLimit = 1 << 22;  // as snapTriangle: the conversion to fixed point stays defined
constexpr std::int32_t kHalfWidth = 128;  // half a pixel on the grid: the segment's width is 1

bool sign(float x) { return x >= 0.0f; }
float fraction(float f) { return f - std::floor(f); }

// An attribute's plane along the segment (the header's formula).
Plane segmentPlane(float a1, float a2, float dx, float dy, float oneOverArea, float x1, float y1) {
  const float da21 = a1 - a2;
  Plane p;
  p.dadx = da21 * dx * oneOverArea;
  p.dady = da21 * dy * oneOverArea;
  p.a0 = a1 - (p.dadx * (x1 - 0.5f) + p.dady * (y1 - 0.5f));
  return p;
}

Plane constantPlane(float a) {
  Plane p;
  p.a0 = a;
  return p;
}

// Edge i → i+1 of a convex quad on the grid, by the triangle rule (triangle_setup.h).
void quadEdges(const std::int32_t (&X)[4], const std::int32_t (&Y)[4], EdgeFunction (&edges)[4]) {
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    EdgeFunction& e = edges[i];
    e.dcdx = std::int64_t{Y[i]} - Y[j];
    e.dcdy = std::int64_t{X[i]} - X[j];
    e.c = e.dcdx * X[i] - e.dcdy * Y[i];
    if (e.dcdx < 0 || (e.dcdx == 0 && e.dcdy > 0)) e.c += 1;
  }
}

// The bounding pixels of grid coordinates [lo, hi] as lp_setup_line.c rounds them, within [0, size).
bool boxAxis(std::int64_t lo, std::int64_t hi, int size, int adj, int& first, int& last) {
  first = static_cast<int>(std::max<std::int64_t>(0, (lo + 255 + adj) >> 8));
  last = static_cast<int>(std::min<std::int64_t>(size - 1, ((hi + 255 + adj) >> 8) - 1));
  return first <= last;
}

}  // namespace

bool setUpSegment(const LineVertex& a, const LineVertex& b, int width, int height, LineEndTest ends, RasterLine& out) {
  for (const LineVertex* v : {&a, &b})
    if (!(std::fabs(v->x) < kGridLimit && std::fabs(v->y) < kGridLimit)) return false;
  const float dx = a.x - b.x, dy = a.y - b.y;
  const float area = dx * dx + dy * dy;
  if (area == 0.0f) return false;
  const float oneOverArea = 1.0f / area;
  float planeDx = dx, planeDy = dy;  // "the preferred wide-lines formula": along the major axis only

  const float x1diff = a.x - std::floor(a.x) - 0.5f, y1diff = a.y - std::floor(a.y) - 0.5f;
  float x2diff = b.x - std::floor(b.x) - 0.5f, y2diff = b.y - std::floor(b.y) - 0.5f;
  float xOffset = 0, yOffset = 0, xOffsetEnd = 0, yOffsetEnd = 0;
  const LineVertex* v1 = &a;
  const LineVertex* v2 = &b;
  std::int32_t X[4], Y[4];
  if (std::fabs(dx) >= std::fabs(dy)) {  // x-major
    const float dydx = dy / dx;
    if (y2diff == -0.5f && dy < 0.0f) y2diff = 0.5f;
    // Diamond exit: is the start's pixel drawn, is the end's?
    bool drawStart, drawEnd;
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f) drawStart = true;
    else if (sign(x1diff) == sign(-dx)) drawStart = false;
    else if (sign(-y1diff) != sign(dy)) drawStart = true;
    else {
      const float yIntersect = fraction(a.y) + x1diff * dydx;
      drawStart = yIntersect < 1.0f && yIntersect > 0.0f;
    }
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f) drawEnd = false;
    else if (sign(x2diff) != sign(-dx)) drawEnd = false;
    else if (sign(-y2diff) == sign(dy)) drawEnd = true;
    else {
      const float yIntersect = fraction(b.y) + x2diff * dydx;
      drawEnd = yIntersect < 1.0f && yIntersect > 0.0f;
    }
    planeDx *= 1.0f + dydx * dydx;
    planeDy = 0.0f;
    // Move the ends whose pixel the plain quad would get wrong. Would the
    // plain quad draw them? Mesa 22.3 by the signs of the offsets from the
    // pixel centres; Mesa 25.0 by the quad's edge each end is on (with GL's
    // fill convention, bottom_edge_rule = 0: a left end is drawn when
    // x·diff > 0, a right one when ≤ 0). Only an offset of 0 tells them apart.
    const bool mesa22 = ends == LineEndTest::Mesa22;
    const bool willDrawStart = mesa22 ? sign(-x1diff) != sign(dx) : (dx < 0.0f ? x1diff <= 0.0f : x1diff > 0.0f);
    const bool willDrawEnd = mesa22 ? sign(x2diff) == sign(-dx) || x2diff == 0.0f : (dx < 0.0f ? x2diff > 0.0f : x2diff <= 0.0f);
    if (dx < 0.0f) {
      std::swap(v1, v2);
      if (willDrawStart != drawStart) xOffsetEnd = -x1diff - 0.5f, yOffsetEnd = xOffsetEnd * dydx;
      if (willDrawEnd != drawEnd) xOffset = -x2diff - 0.5f, yOffset = xOffset * dydx;
    } else {
      if (willDrawStart != drawStart) xOffset = -x1diff + 0.5f, yOffset = xOffset * dydx;
      if (willDrawEnd != drawEnd) xOffsetEnd = -x2diff + 0.5f, yOffsetEnd = xOffsetEnd * dydx;
    }
    X[0] = X[3] = snapToGrid(v1->x + xOffset);
    X[1] = X[2] = snapToGrid(v2->x + xOffsetEnd);
    Y[0] = snapToGrid(v1->y + yOffset) - kHalfWidth;
    Y[1] = snapToGrid(v2->y + yOffsetEnd) - kHalfWidth;
    Y[2] = snapToGrid(v2->y + yOffsetEnd) + kHalfWidth;
    Y[3] = snapToGrid(v1->y + yOffset) + kHalfWidth;
  } else {  // y-major
    const float dxdy = dx / dy;
    if (x2diff == -0.5f && dx < 0.0f) x2diff = 0.5f;
    bool drawStart, drawEnd;
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f) drawStart = true;
    else if (sign(-y1diff) == sign(dy)) drawStart = false;
    else if (sign(x1diff) != sign(-dx)) drawStart = true;
    else {
      const float xIntersect = fraction(a.x) + y1diff * dxdy;
      drawStart = xIntersect < 1.0f && xIntersect > 0.0f;
    }
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f) drawEnd = false;
    else if (sign(-y2diff) != sign(dy)) drawEnd = false;
    else if (sign(x2diff) == sign(-dx)) drawEnd = true;
    else {
      const float xIntersect = fraction(b.x) + y2diff * dxdy;
      drawEnd = xIntersect < 1.0f && xIntersect >= 0.0f;
    }
    planeDx = 0.0f;
    planeDy *= 1.0f + dxdy * dxdy;
    // As x-major: Mesa 25.0 by the bottom or top edge each end is on.
    const bool mesa22 = ends == LineEndTest::Mesa22;
    const bool willDrawStart = mesa22 ? sign(y1diff) == sign(dy) : (dy > 0.0f ? y1diff > 0.0f : y1diff <= 0.0f);
    const bool willDrawEnd = mesa22 ? sign(-y2diff) == sign(dy) || y2diff == 0.0f : (dy > 0.0f ? y2diff <= 0.0f : y2diff > 0.0f);
    if (dy > 0.0f) {
      std::swap(v1, v2);
      if (willDrawStart != drawStart) yOffsetEnd = -y1diff + 0.5f, xOffsetEnd = yOffsetEnd * dxdy;
      if (willDrawEnd != drawEnd) yOffset = -y2diff + 0.5f, xOffset = yOffset * dxdy;
    } else {
      if (willDrawStart != drawStart) yOffset = -y1diff - 0.5f, xOffset = yOffset * dxdy;
      if (willDrawEnd != drawEnd) yOffsetEnd = -y2diff - 0.5f, xOffsetEnd = yOffsetEnd * dxdy;
    }
    X[0] = snapToGrid(v1->x + xOffset) - kHalfWidth;
    X[1] = snapToGrid(v2->x + xOffsetEnd) - kHalfWidth;
    X[2] = snapToGrid(v2->x + xOffsetEnd) + kHalfWidth;
    X[3] = snapToGrid(v1->x + xOffset) + kHalfWidth;
    Y[0] = Y[3] = snapToGrid(v1->y + yOffset);
    Y[1] = Y[2] = snapToGrid(v2->y + yOffsetEnd);
  }

  if (!boxAxis(std::min({X[0], X[1], X[2], X[3]}), std::max({X[0], X[1], X[2], X[3]}), width, 0, out.box.minX, out.box.maxX) ||
      !boxAxis(std::min({Y[0], Y[1], Y[2], Y[3]}), std::max({Y[0], Y[1], Y[2], Y[3]}), height, 0, out.box.minY, out.box.maxY))
    return false;
  quadEdges(X, Y, out.edges);
  // The planes start from the first vertex as submitted, whichever end the quad starts from.
  out.z = segmentPlane(a.z, b.z, planeDx, planeDy, oneOverArea, a.x, a.y);
  out.oneOverW = segmentPlane(a.invW, b.invW, planeDx, planeDy, oneOverArea, a.x, a.y);
  for (int k = 0; k < 3; ++k)
    out.color[k] = segmentPlane(a.color[k] * a.invW, b.color[k] * b.invW, planeDx, planeDy, oneOverArea, a.x, a.y);
  return true;
}

bool setUpPoint(const LineVertex& v, int width, int height, RasterLine& out) {
  if (!(std::fabs(v.x) < kGridLimit && std::fabs(v.y) < kGridLimit)) return false;
  constexpr std::int32_t kSize = 256;  // size 1 on the grid
  const std::int32_t x0 = snapToGrid(v.x) - kSize / 2, y0 = snapToGrid(v.y) - kSize / 2;
  const std::int32_t x1 = x0 + kSize, y1 = y0 + kSize;
  out.box.minX = std::max(0, x0 >> 8);
  out.box.maxX = std::min(width - 1, ((x1 + 255) >> 8) - 1);
  out.box.minY = std::max(0, y0 >> 8);
  out.box.maxY = std::min(height - 1, ((y1 + 255) >> 8) - 1);
  if (out.box.minX > out.box.maxX || out.box.minY > out.box.maxY) return false;
  // Four axis-aligned edges: 256·px ≥ x0 (left, inclusive), 256·px < x1, 256·py ≥ y0 (bottom, inclusive), 256·py < y1.
  out.edges[0] = {-std::int64_t{x0} + 1, -1, 0};
  out.edges[1] = {std::int64_t{x1}, 1, 0};
  out.edges[2] = {-std::int64_t{y0} + 1, 0, 1};
  out.edges[3] = {std::int64_t{y1}, 0, -1};
  out.z = constantPlane(v.z);
  out.oneOverW = constantPlane(v.invW);
  for (int k = 0; k < 3; ++k) out.color[k] = constantPlane(v.color[k] * v.invW);
  return true;
}

}  // namespace facet::cpu
