// The resolve four pixels (sixteen channels) at a time: the only other
// translation unit built with -mavx512f (renderer/cpu/CMakeLists.txt). As in
// phong_batch_avx512.cpp, nothing here may leave an out-of-line copy of a
// function another translation unit also defines: the entry point is
// flattened, and tests/cpu/wide_symbols.cmake holds it.
//
// The level of a channel is the table's (image/srgb.h), found without its
// look-ups: an estimate of 255·E(c) in float, within 3.6e-4 of the exact
// value over every float of [0, 1] (measured), gives floor(255·E(c) + 0.5)
// wherever that estimate + 0.5 lies more than kNear from an integer; the
// few channels nearer than that (0.26 % of a sphere-100k frame's) take the
// bucket table's look-up. tests/cpu/test_fast_paths.cpp holds the result
// to the thresholds for every float of [0, 1].
#include <cstddef>
#include <cstdint>

#include "shading/resolve.h"
#include "image/srgb.h"

#if !defined(__AVX512F__)
#error "resolve_avx512.cpp is built with -mavx512f"
#endif
#include <immintrin.h>

namespace facet {
namespace {

constexpr float kNear = 0.002f;  // levels: over five times the estimate's largest error

// 255·E(c) for c in [0, 1]: c^(1/2.4) = 2^(-k/2.4)·m^(1/2.4) with c = m·2^-k,
// m in [1, 2) (kOctave[k] = 2^(-k/2.4); below 2^-15 c is on the linear
// part), m^(1/2.4) by a degree-5 fit (kSrgbGamma = 2.4).
inline __m512 levelEstimate(__m512 c) {
  alignas(64) static constexpr float kOctave[16] = {1.0f,           7.491535384e-01f, 5.612310242e-01f, 4.204482076e-01f,
                                                    3.149802625e-01f, 2.359685782e-01f, 1.767766953e-01f, 1.324328868e-01f,
                                                    9.921256575e-02f, 7.432544469e-02f, 5.568116988e-02f, 4.171374544e-02f,
                                                    3.125000000e-02f, 2.341104808e-02f, 1.753846950e-02f, 1.313900649e-02f};
  const __m512i k = _mm512_min_epi32(_mm512_cvttps_epi32(_mm512_sub_ps(_mm512_setzero_ps(), _mm512_getexp_ps(c))), _mm512_set1_epi32(15));
  const __m512 m = _mm512_sub_ps(_mm512_getmant_ps(c, _MM_MANT_NORM_1_2, _MM_MANT_SIGN_src), _mm512_set1_ps(1.5f));
  __m512 p = _mm512_fmadd_ps(m, _mm512_set1_ps(0.00533292326f), _mm512_set1_ps(-0.0106548548f));
  p = _mm512_fmadd_ps(p, m, _mm512_set1_ps(0.0223936171f));
  p = _mm512_fmadd_ps(p, m, _mm512_set1_ps(-0.0638602023f));
  p = _mm512_fmadd_ps(p, m, _mm512_set1_ps(0.328908141f));
  p = _mm512_fmadd_ps(p, m, _mm512_set1_ps(1.18405227f));
  const __m512 root = _mm512_mul_ps(p, _mm512_permutexvar_ps(k, _mm512_load_ps(kOctave)));
  const __m512 curve = _mm512_fmadd_ps(root, _mm512_set1_ps(static_cast<float>(255.0 * kSrgbScale)), _mm512_set1_ps(static_cast<float>(-255.0 * kSrgbOffset)));
  return _mm512_mask_mul_ps(curve, _mm512_cmp_ps_mask(c, _mm512_set1_ps(static_cast<float>(kSrgbLinearEnd)), _CMP_LE_OQ), c, _mm512_set1_ps(static_cast<float>(255.0 * kSrgbSlope)));
}

}  // namespace

__attribute__((flatten)) void resolveSixteenLanes(const glm::vec4* in, Rgba8* out, std::size_t n, bool premultiplied, int samples) {
  const SrgbTables& t = srgbTables();
  const float* from = &in[0].r;
  const __m512 one = _mm512_set1_ps(1.0f), zero = _mm512_setzero_ps();
  constexpr __mmask16 kAlpha = 0x8888, kColour = 0x7777;
  for (std::size_t i = 0; i < n; i += 4) {
    const __mmask16 lanes = n - i >= 4 ? __mmask16{0xFFFF} : static_cast<__mmask16>((1u << (4 * (n - i))) - 1u);
    __m512 x = _mm512_maskz_loadu_ps(lanes, from + 4 * i);
    if (samples != 1) x = _mm512_div_ps(x, _mm512_set1_ps(static_cast<float>(samples)));  // the sum / samples
    if (premultiplied) {  // unstored: C / a where a > 0, else 0; a as held
      const __m512 a = _mm512_permute_ps(x, 0xFF);
      x = _mm512_mask_blend_ps(kAlpha, _mm512_maskz_mov_ps(_mm512_cmp_ps_mask(a, zero, _CMP_GT_OQ), _mm512_div_ps(x, a)), x);
    }
    const __m512 c = _mm512_maskz_min_ps(_mm512_cmp_ps_mask(x, zero, _CMP_GT_OQ), x, one);  // clampUnit
    const __m512 half = _mm512_add_ps(levelEstimate(c), _mm512_set1_ps(0.5f));
    const __m512 level = _mm512_roundscale_ps(half, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    const __m512 off = _mm512_abs_ps(_mm512_sub_ps(_mm512_sub_ps(half, level), _mm512_set1_ps(0.5f)));
    const __mmask16 near = _mm512_cmp_ps_mask(off, _mm512_set1_ps(0.5f - kNear), _CMP_GT_OQ) & kColour & lanes;
    // alphaLevel: clamped·255 + 0.5, truncated (a product and a sum, each rounded once)
    const __m512i alpha = _mm512_cvttps_epi32(_mm512_add_ps(_mm512_mul_ps(c, _mm512_set1_ps(255.0f)), _mm512_set1_ps(0.5f)));
    __m512i levels = _mm512_mask_blend_epi32(kAlpha, _mm512_cvttps_epi32(level), alpha);
    if (near) {  // the bucket table's look-up (encodeLevel) for the channels near a level's edge, by gathers
      const __m512i bits = _mm512_castps_si512(_mm512_max_ps(c, _mm512_set1_ps(kSrgbFloor)));  // encodeLevel's clamp, c being in [0, 1]
      const __m512i bucket = _mm512_sub_epi32(_mm512_srli_epi32(bits, kSrgbBucketShift), _mm512_set1_epi32(kSrgbFirstBucket));
      const __m512i entry = _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), near, bucket, t.buckets.data(), 4);
      const __m512i byTable = _mm512_srli_epi32(_mm512_add_epi32(entry, _mm512_and_si512(bits, _mm512_set1_epi32(kSrgbInBucket))), kSrgbBucketShift);  // levelInBucket
      levels = _mm512_mask_blend_epi32(near, levels, byTable);
    }
    _mm512_mask_cvtepi32_storeu_epi8(out + i, lanes, levels);
  }
}

}  // namespace facet
