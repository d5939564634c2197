#pragma once
// Coverage of one binned triangle inside one tile, in 8×8 blocks first (as
// llvmpipe's rasterizer does): a block whose pixel centres all lie outside
// one edge is skipped, one with all centres inside every edge is taken
// whole, and only the rest are tested pixel by pixel. The edge functions and
// the test are those of triangle_setup.h (c - dcdx·256·px + dcdy·256·py > 0),
// so the covered pixels are the same; fragments come in row order per block.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "cpu/frame_buffers.h"
#include "cpu/triangle_setup.h"

namespace facet::cpu {

// Calls visit(bins, index, triangle, vertices, box) for each triangle
// binned to `tile` whose pixel box reaches into r, in submission order
// (worker 0's bins first), with that box clipped to r; vertices[k] views the
// triangle's packed window vertex k, in set-up order.
template <class Visit>
void forEachTriangleInTile(const std::vector<WorkerBins>& workers, const PassVertices& v, int tile, const TileRect& r, Visit&& visit) {
  for (const WorkerBins& bins : workers)
    for (const std::uint32_t index : bins.tiles[static_cast<std::size_t>(tile)]) {
      const BinnedTriangle& t = bins.triangles[index];
      PixelBox box;
      if (!pixelBox(t.snapped, r.x0, r.y0, r.x1, r.y1, box)) continue;
      InterpolationVertex vertices[3];
      for (int k = 0; k < 3; ++k) {
        const float* p = bins.vertex(v, t.vertex[k]);
        vertices[k] = {p[0], p[1], p[2], p[3], p + 4};
      }
      visit(bins, index, t, vertices, box);
    }
}

// fragment(px, py) for each covered pixel of the box, except that a row of
// a block wholly inside the triangle goes to span(x0, x1, py) at once (the
// depth tests run it four pixels at a time: depth_rows.h). The pixels of one
// triangle are distinct, so the order they come in changes nothing.
template <class Fragment, class Span>
void rasterizeBlocks(const SnappedTriangle& t, const PixelBox& box, Fragment&& fragment, Span&& span) {
  EdgeFunction edges[3];
  edgeFunctions(t, edges);
  std::int64_t c[3], sx[3], sy[3];  // value at pixel (0, 0), step per pixel in x and in y
  for (int i = 0; i < 3; ++i) {
    c[i] = edges[i].c;
    sx[i] = -edges[i].dcdx * 256;
    sy[i] = edges[i].dcdy * 256;
  }
  const int minX = box.minX, minY = box.minY, maxX = box.maxX, maxY = box.maxY;
  for (int by = minY & ~7; by <= maxY; by += 8) {
    const int y0 = std::max(by, minY), y1 = std::min(by + 7, maxY);
    for (int bx = minX & ~7; bx <= maxX; bx += 8) {
      const int x0 = std::max(bx, minX), x1 = std::min(bx + 7, maxX);
      std::int64_t e[3];
      bool outside = false, inside = true;
      for (int i = 0; i < 3; ++i) {
        e[i] = c[i] + sx[i] * x0 + sy[i] * y0;
        const std::int64_t ex = sx[i] * (x1 - x0), ey = sy[i] * (y1 - y0);
        const std::int64_t hi = e[i] + std::max<std::int64_t>(ex, 0) + std::max<std::int64_t>(ey, 0);
        const std::int64_t lo = e[i] + std::min<std::int64_t>(ex, 0) + std::min<std::int64_t>(ey, 0);
        outside |= hi <= 0;
        inside &= lo > 0;
      }
      if (outside) continue;
      if (inside) {
        for (int py = y0; py <= y1; ++py) span(x0, x1, py);
        continue;
      }
      for (int py = y0; py <= y1; ++py) {
        std::int64_t w0 = e[0], w1 = e[1], w2 = e[2];
        for (int px = x0; px <= x1; ++px) {
          if (w0 > 0 && w1 > 0 && w2 > 0) fragment(px, py);
          w0 += sx[0];
          w1 += sx[1];
          w2 += sx[2];
        }
        e[0] += sy[0];
        e[1] += sy[1];
        e[2] += sy[2];
      }
    }
  }
}

template <class Fragment>
void rasterizeBlocks(const SnappedTriangle& t, const PixelBox& box, Fragment&& fragment) {
  rasterizeBlocks(t, box, fragment, [&](int x0, int x1, int py) {
    for (int px = x0; px <= x1; ++px) fragment(px, py);
  });
}

}  // namespace facet::cpu
