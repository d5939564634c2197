#pragma once
// Coverage of one binned triangle inside one tile, in 8×8 blocks first (as
// llvmpipe's rasterizer does): a block whose pixel centres all lie outside
// one edge is skipped, one with all centres inside every edge is taken
// whole, and only the rest are tested pixel by pixel. The edge functions and
// the test are those of triangle_setup.h (c - dcdx·256·px + dcdy·256·py > 0),
// so the covered pixels are the same; fragments come in row order per block.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "cpu/frame_buffers.h"
#include "cpu/triangle_setup.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

// How far an edge's value moves across an 8x8 block and one row step past
// it: 8·(|step x| + |step y|). A block whose first pixel's values e all have
// |e| + reach below 2^31 has every edge value in 32 bits.
inline std::int64_t blockReach(std::int64_t sx, std::int64_t sy) { return 8 * (std::abs(sx) + std::abs(sy)); }
inline bool fitsInt32(const std::int64_t (&e)[3], const std::int64_t (&reach)[3]) {
  constexpr std::int64_t kLimit = std::int64_t{1} << 31;
  return std::abs(e[0]) + reach[0] < kLimit && std::abs(e[1]) + reach[1] < kLimit && std::abs(e[2]) + reach[2] < kLimit;
}

#if defined(__SSE2__)
// A block on an edge of the triangle, its edge values in 32 bits: each row's
// eight coverage tests at once, as the sign of -w0 & -w1 & -w2 (all three
// w > 0 exactly when all three -w are negative), then the row to
// span(x0, x1, py) when it is covered whole, else its covered pixels to
// covered(bx, bits, py) (rasterizeBlocks).
template <class Span, class Covered>
void partialBlock(const std::int64_t (&e)[3], const std::int64_t (&sx)[3], const std::int64_t (&sy)[3], int x0, int x1, int y0, int y1,
                  Span& span, Covered& covered) {
  __m128i low[3], high[3], down[3];  // -w at columns x0..x0+3 and x0+4..x0+7 of the row; -(step y)
  for (int i = 0; i < 3; ++i) {
    const auto w = static_cast<std::int32_t>(-e[i]), step = static_cast<std::int32_t>(-sx[i]);  // in range: fitsInt32
    low[i] = _mm_add_epi32(_mm_set1_epi32(w), _mm_setr_epi32(0, step, 2 * step, 3 * step));
    high[i] = _mm_add_epi32(low[i], _mm_set1_epi32(4 * step));
    down[i] = _mm_set1_epi32(static_cast<std::int32_t>(-sy[i]));
  }
  const unsigned whole = (1u << (x1 - x0 + 1)) - 1u;
  for (int py = y0; py <= y1; ++py) {
    const __m128 l = _mm_castsi128_ps(_mm_and_si128(_mm_and_si128(low[0], low[1]), low[2]));
    const __m128 h = _mm_castsi128_ps(_mm_and_si128(_mm_and_si128(high[0], high[1]), high[2]));
    const unsigned bits = (static_cast<unsigned>(_mm_movemask_ps(l)) | static_cast<unsigned>(_mm_movemask_ps(h)) << 4) & whole;
    if (bits == whole) span(x0, x1, py);
    else if (bits != 0) covered(x0 & ~7, bits << (x0 & 7), py);  // from the block's first column
    for (int i = 0; i < 3; ++i) {
      low[i] = _mm_add_epi32(low[i], down[i]);
      high[i] = _mm_add_epi32(high[i], down[i]);
    }
  }
}
#endif

// fragment(px, py) for each covered pixel of the box, except that a row
// wholly inside the triangle (each row across a run of blocks wholly inside,
// side by side, and a block's row on an edge whose pixels all pass) goes to
// span(x0, x1, py) at once (the depth tests run it four or sixteen pixels
// at a time: depth_rows.h), and,
// where SSE2 tests a block's rows eight pixels at once, a row of a block on
// an edge to covered(bx, bits, py): bx the block's first column (a multiple
// of 8), bit k of `bits` set where pixel bx + k is covered. The pixels of
// one triangle are distinct, so the order they come in changes nothing.
template <class Fragment, class Span, class Covered>
void rasterizeBlocks(const SnappedTriangle& t, const PixelBox& box, Fragment&& fragment, Span&& span, Covered&& covered) {
  EdgeFunction edges[3];
  edgeFunctions(t, edges);
  std::int64_t c[3], sx[3], sy[3];  // value at pixel (0, 0), step per pixel in x and in y
  for (int i = 0; i < 3; ++i) {
    c[i] = edges[i].c;
    sx[i] = -edges[i].dcdx * 256;
    sy[i] = edges[i].dcdy * 256;
  }
#if defined(__SSE2__)
  const std::int64_t reach[3] = {blockReach(sx[0], sy[0]), blockReach(sx[1], sy[1]), blockReach(sx[2], sy[2])};
#endif
  const int minX = box.minX, minY = box.minY, maxX = box.maxX, maxY = box.maxY;
  for (int by = minY & ~7; by <= maxY; by += 8) {
    const int y0 = std::max(by, minY), y1 = std::min(by + 7, maxY);
    // Blocks wholly inside, side by side, go to span as one run per row (columns inside0..inside1):
    // one depth-test call for a row of the tile instead of one per block.
    int inside0 = 0, inside1 = -1;
    const auto handOver = [&] {
      for (int py = y0; py <= y1 && inside0 <= inside1; ++py) span(inside0, inside1, py);
    };
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
        if (inside0 > inside1 || inside1 + 1 != x0) {  // not next to the run (a convex triangle's inside blocks are, in a row of blocks)
          handOver();
          inside0 = x0;
        }
        inside1 = x1;
        continue;
      }
#if defined(__SSE2__)
      if (fitsInt32(e, reach)) {
        partialBlock(e, sx, sy, x0, x1, y0, y1, span, covered);
        continue;
      }
#endif
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
    handOver();
  }
}

// The same with a block's covered pixels of a row on an edge each to fragment.
template <class Fragment, class Span>
void rasterizeBlocks(const SnappedTriangle& t, const PixelBox& box, Fragment&& fragment, Span&& span) {
  rasterizeBlocks(t, box, fragment, span, [&](int bx, unsigned bits, int py) {
    for (; bits != 0; bits &= bits - 1) fragment(bx + __builtin_ctz(bits), py);
  });
}

template <class Fragment>
void rasterizeBlocks(const SnappedTriangle& t, const PixelBox& box, Fragment&& fragment) {
  rasterizeBlocks(t, box, fragment, [&](int x0, int x1, int py) {
    for (int px = x0; px <= x1; ++px) fragment(px, py);
  });
}

}  // namespace facet::cpu
