#pragma once
// The LESS depth test over a run of pixels of one row of one triangle, four
// pixels at a time where SSE2 is there (sixteen where the frame shades
// sixteen lanes: lessRowOnLanes, frontRowOnLanes below): each lane's window z is depthAt's
// (planeAt4: the same two fused multiply-adds; minps then maxps: the same
// clamp, NaN to 1), compared and written as the one-pixel test does. For
// the runs rasterizeBlocks hands over whole (tile_raster.h): an opaque
// triangle's (lessRow, depth written) and a blended one's (frontRow, depth
// only read).
#include <cstdint>

#include "cpu/plane_equations.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace facet::cpu {

// Pixels x0..x1 of row py: where depthAt(z, px, py) < depth[px - x0], that
// depth takes it, and ids[px - x0] takes `id` when ids is not null.
#if defined(__SSE2__)
// depthAt of pixels px..px+3 of row py.
inline __m128 depthAt4(const Plane& z, int px, int py) { return _mm_max_ps(_mm_min_ps(planeAt4(z, px, py), _mm_set1_ps(1.0f)), _mm_setzero_ps()); }
#endif

inline void lessRow(const Plane& z, int x0, int x1, int py, float* depth, std::uint32_t* ids, std::uint32_t id) {
  int px = x0;
#if defined(__SSE2__)
  const __m128i idLanes = _mm_set1_epi32(static_cast<int>(id));
  for (; px + 3 <= x1; px += 4) {
    const __m128 w = depthAt4(z, px, py);
    float* d = depth + (px - x0);
    const __m128 stored = _mm_loadu_ps(d);
    const __m128 less = _mm_cmplt_ps(w, stored);
    if (_mm_movemask_ps(less) == 0) continue;
    _mm_storeu_ps(d, _mm_or_ps(_mm_and_ps(less, w), _mm_andnot_ps(less, stored)));
    if (!ids) continue;
    auto* i = reinterpret_cast<__m128i*>(ids + (px - x0));
    const __m128i mask = _mm_castps_si128(less);
    _mm_storeu_si128(i, _mm_or_si128(_mm_and_si128(mask, idLanes), _mm_andnot_si128(mask, _mm_loadu_si128(i))));
  }
#endif
  for (; px <= x1; ++px) {
    const float w = depthAt(z, px, py);
    if (!(w < depth[px - x0])) continue;
    depth[px - x0] = w;
    if (ids) ids[px - x0] = id;
  }
}

// lessRow for the pixels bx + k of row py whose bit k is set in `covered`
// (k < 8; bx a block's first column): a row of a block on the triangle's
// edge (tile_raster.h). depth and ids are pixel bx's, with room for eight.
inline void lessCovered(const Plane& z, int bx, unsigned covered, int py, float* depth, std::uint32_t* ids, std::uint32_t id) {
#if defined(__SSE2__)
  const __m128i laneBit = _mm_setr_epi32(1, 2, 4, 8), idLanes = _mm_set1_epi32(static_cast<int>(id));
  for (int q = 0; q < 8; q += 4) {
    const unsigned bits = (covered >> q) & 0xFu;
    if (bits == 0) continue;
    const __m128 on = _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(static_cast<int>(bits)), laneBit), laneBit));
    float* d = depth + q;
    const __m128 w = depthAt4(z, bx + q, py), stored = _mm_loadu_ps(d);
    const __m128 less = _mm_and_ps(_mm_cmplt_ps(w, stored), on);
    if (_mm_movemask_ps(less) == 0) continue;
    _mm_storeu_ps(d, _mm_or_ps(_mm_and_ps(less, w), _mm_andnot_ps(less, stored)));
    if (!ids) continue;
    auto* i = reinterpret_cast<__m128i*>(ids + q);
    const __m128i mask = _mm_castps_si128(less);
    _mm_storeu_si128(i, _mm_or_si128(_mm_and_si128(mask, idLanes), _mm_andnot_si128(mask, _mm_loadu_si128(i))));
  }
#else
  for (; covered != 0; covered &= covered - 1) {
    const int k = __builtin_ctz(covered);
    const float w = depthAt(z, bx + k, py);
    if (!(w < depth[k])) continue;
    depth[k] = w;
    if (ids) ids[k] = id;
  }
#endif
}

// Pixels x0..x1 of row py: where depthAt(z, px, py) < depth[px - x0] (a
// blended fragment in front of the opaque surfaces; the depth is not
// written), ids[px - x0] takes `id`. Returns the first and last pixel
// taken (first > last: none).
struct TakenRun {
  int first, last;
};
inline TakenRun frontRow(const Plane& z, int x0, int x1, int py, const float* depth, std::uint32_t* ids, std::uint32_t id) {
  TakenRun taken{x1 + 1, x0 - 1};
  int px = x0;
#if defined(__SSE2__)
  const __m128i idLanes = _mm_set1_epi32(static_cast<int>(id));
  for (; px + 3 <= x1; px += 4) {
    const __m128 lessLanes = _mm_cmplt_ps(depthAt4(z, px, py), _mm_loadu_ps(depth + (px - x0)));
    const int less = _mm_movemask_ps(lessLanes);
    if (less == 0) continue;
    auto* i = reinterpret_cast<__m128i*>(ids + (px - x0));
    const __m128i mask = _mm_castps_si128(lessLanes);
    _mm_storeu_si128(i, _mm_or_si128(_mm_and_si128(mask, idLanes), _mm_andnot_si128(mask, _mm_loadu_si128(i))));
    if (taken.first > x1) taken.first = px + __builtin_ctz(static_cast<unsigned>(less));
    taken.last = px + 31 - __builtin_clz(static_cast<unsigned>(less));
  }
#endif
  for (; px <= x1; ++px) {
    if (!(depthAt(z, px, py) < depth[px - x0])) continue;
    ids[px - x0] = id;
    if (taken.first > x1) taken.first = px;
    taken.last = px;
  }
  return taken;
}

#if defined(FACET_AVX512_LANES)
// lessRow and frontRow sixteen pixels at a time, the same pixels and bits
// (depth_rows_avx512.cpp; call only where widestLanes() is 16).
void lessRowSixteen(const Plane& z, int x0, int x1, int py, float* depth, std::uint32_t* ids, std::uint32_t id);
TakenRun frontRowSixteen(const Plane& z, int x0, int x1, int py, const float* depth, std::uint32_t* ids, std::uint32_t id);
#endif

// lessRow and frontRow for a frame shading `lanes` lanes: sixteen at a time
// where that is 16 (depth_rows.cpp, which is built knowing whether the
// sixteen-lane code is there).
void lessRowOnLanes(int lanes, const Plane& z, int x0, int x1, int py, float* depth, std::uint32_t* ids, std::uint32_t id);
TakenRun frontRowOnLanes(int lanes, const Plane& z, int x0, int x1, int py, const float* depth, std::uint32_t* ids, std::uint32_t id);

}  // namespace facet::cpu
