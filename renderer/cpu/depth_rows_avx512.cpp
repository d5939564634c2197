// The depth tests of depth_rows.h sixteen pixels at a time: the third
// translation unit built with -mavx512f (renderer/cpu/CMakeLists.txt). As in
// phong_batch_avx512.cpp, nothing here may leave an out-of-line copy of a
// function another translation unit also defines: the entry points are
// flattened, and tests/cpu/wide_symbols.cmake holds them.
//
// Each lane's window z is depthAt's: the plane's two fused multiply-adds,
// then vminps and vmaxps (the same clamp, NaN to 1, as minps and maxps); a
// row's last pixels are masked lanes, so no pixel past x1 is read or written.
#include "cpu/depth_rows.h"

#if !defined(__AVX512F__)
#error "depth_rows_avx512.cpp is built with -mavx512f"
#endif
#include <immintrin.h>

namespace facet::cpu {
namespace {

// depthAt of pixels px .. px+15 of row py.
inline __m512 depthAt16(const Plane& z, int px, int py) {
  const __m512 x = _mm512_add_ps(_mm512_set1_ps(static_cast<float>(px)),
                                 _mm512_setr_ps(0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f, 8.0f, 9.0f, 10.0f, 11.0f, 12.0f, 13.0f, 14.0f, 15.0f));
  const __m512 at = _mm512_fmadd_ps(_mm512_set1_ps(z.dady), _mm512_set1_ps(static_cast<float>(py)), _mm512_fmadd_ps(_mm512_set1_ps(z.dadx), x, _mm512_set1_ps(z.a0)));
  return _mm512_max_ps(_mm512_min_ps(at, _mm512_set1_ps(1.0f)), _mm512_setzero_ps());
}

// The lanes of pixels px .. min(px + 15, x1).
inline __mmask16 lanesTo(int px, int x1) { return x1 - px >= 15 ? __mmask16{0xFFFF} : static_cast<__mmask16>((1u << (x1 - px + 1)) - 1u); }

}  // namespace

__attribute__((flatten)) void lessRowSixteen(const Plane& z, int x0, int x1, int py, float* depth, std::uint32_t* ids, std::uint32_t id) {
  const __m512i idLanes = _mm512_set1_epi32(static_cast<int>(id));
  for (int px = x0; px <= x1; px += 16) {
    const __mmask16 on = lanesTo(px, x1);
    float* d = depth + (px - x0);
    const __m512 w = depthAt16(z, px, py);
    const __mmask16 less = _mm512_mask_cmp_ps_mask(on, w, _mm512_maskz_loadu_ps(on, d), _CMP_LT_OQ);
    _mm512_mask_storeu_ps(d, less, w);
    if (ids) _mm512_mask_storeu_epi32(ids + (px - x0), less, idLanes);
  }
}

__attribute__((flatten)) TakenRun frontRowSixteen(const Plane& z, int x0, int x1, int py, const float* depth, std::uint32_t* ids, std::uint32_t id) {
  TakenRun taken{x1 + 1, x0 - 1};
  const __m512i idLanes = _mm512_set1_epi32(static_cast<int>(id));
  for (int px = x0; px <= x1; px += 16) {
    const __mmask16 on = lanesTo(px, x1);
    const __mmask16 less = _mm512_mask_cmp_ps_mask(on, depthAt16(z, px, py), _mm512_maskz_loadu_ps(on, depth + (px - x0)), _CMP_LT_OQ);
    if (less == 0) continue;
    _mm512_mask_storeu_epi32(ids + (px - x0), less, idLanes);
    if (taken.first > x1) taken.first = px + __builtin_ctz(less);
    taken.last = px + 31 - __builtin_clz(less);
  }
  return taken;
}

}  // namespace facet::cpu
