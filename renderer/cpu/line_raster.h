#pragma once
// Segments and points set up for coverage and interpolation as llvmpipe
// does it, so that both backends cover the same pixels with the same depth
// and colour (renderer/PIPELINE.md, "Lines and points"). Read
// from Mesa's lp_setup_line.c (try_setup_line, the diamond-exit branch:
// GL's lines are not rectangular unless smoothed) and lp_setup_point.c
// (try_setup_point, points as quads), and checked against llvmpipe
// (tests/gl/test_line_raster.cpp).
//
// A segment of width 1 becomes a parallelogram: its ends on the 1/256 grid,
// moved along the major axis where the diamond-exit rule says an end pixel
// is (or is not) drawn and the plain quad would not (or would) draw it (the
// second test as the llvmpipe held against makes it: LineEndTest), widened
// by ±1/2 pixel across the minor axis. Its
// four edges cover a pixel by the triangle rule (triangle_setup.h). Its
// attributes vary along the major axis only:
//
//   x-major:  dadx = ((a1 - a2)·(dx·(1 + (dy/dx)²)))·(1/(dx² + dy²)),  dady = 0
//   y-major:  dady = ((a1 - a2)·(dy·(1 + (dx/dy)²)))·(1/(dx² + dy²)),  dadx = 0
//   a(0) = a1 - (dadx·(x1 - 0.5) + dady·(y1 - 0.5))
//
// with (dx, dy) = v1 - v2 in submitted order, evaluated as plane_equations.h's
// Plane::at. A point of size 1 is the square of side 1 around its centre,
// its left and bottom edges inclusive; depth and 1/w are the vertex's.
#include <cstdint>

#include <glm/vec3.hpp>

#include "cpu/plane_equations.h"
#include "pipeline/frame_inputs.h"
#include "cpu/triangle_setup.h"

namespace facet::cpu {

// What the set-up reads of a window vertex: position, 1/w, and its colour (RGB).
struct LineVertex {
  float x, y, z, invW;
  float color[3];
};

// A segment or a point, ready for any pixel of its box.
struct RasterLine {
  EdgeFunction edges[4];
  PixelBox box;                // pixels, inclusive, within the viewport
  Plane z, oneOverW, color[3];  // color: the planes of c·(1/w)

  bool covers(int px, int py) const {
    for (const EdgeFunction& e : edges)
      if (e.at(px, py) <= 0) return false;
    return true;
  }
  // Window z, clamped as a triangle's (plane_equations.h).
  float depthAt(int px, int py) const { return cpu::depthAt(z, px, py); }
  // Channel k of the colour: plane(c·(1/w)) · (1 / plane(1/w)), as a triangle's varyings.
  float colorAt(int k, int px, int py) const { return color[k].at(px, py) * (1.0f / oneOverW.at(px, py)); }
};

// A segment or point of an instance: its raster and its material's O_d.
struct DrawnLine {
  RasterLine raster;
  glm::vec3 baseColor;
};

// Segment a → b in a width × height viewport. False when it covers nothing
// (zero length, off the viewport, or coordinates too large for the grid).
bool setUpSegment(const LineVertex& a, const LineVertex& b, int width, int height, LineEndTest ends, RasterLine& out);

// A point of size 1. False when it covers nothing.
bool setUpPoint(const LineVertex& v, int width, int height, RasterLine& out);

}  // namespace facet::cpu
