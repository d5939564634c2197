#pragma once
// encodePixel (image/srgb.h) of one linear RGBA pixel: the clamps, the
// buckets and the alpha level four lanes at a time where SSE2 is there, then
// the same look-ups; the tables are passed in so a loop looks them up once.
#include <cstdint>

#include "image/image.h"
#include "image/srgb.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace facet {

inline Rgba8 encodePixel4(const SrgbTables& t, const float* rgba) {
#if defined(__SSE2__)
  const __m128 x = _mm_loadu_ps(rgba);
  // (x < 1) ? x : 1 (minps), then 0 unless x > 0 (NaN too): clampUnit; raised to kSrgbFloor for encodeLevel
  const __m128 c = _mm_and_ps(_mm_cmpgt_ps(x, _mm_setzero_ps()), _mm_min_ps(x, _mm_set1_ps(1.0f)));
  const __m128i bits = _mm_castps_si128(_mm_max_ps(c, _mm_set1_ps(kSrgbFloor)));
  alignas(16) std::uint32_t index[4], held[4];
  alignas(16) std::int32_t alpha[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(index), _mm_sub_epi32(_mm_srli_epi32(bits, kSrgbBucketShift), _mm_set1_epi32(kSrgbFirstBucket)));
  _mm_store_si128(reinterpret_cast<__m128i*>(held), bits);
  // alphaLevel: clamped·255 + 0.5, truncated (a product and a sum, each rounded once)
  _mm_store_si128(reinterpret_cast<__m128i*>(alpha), _mm_cvttps_epi32(_mm_add_ps(_mm_mul_ps(c, _mm_set1_ps(255.0f)), _mm_set1_ps(0.5f))));
  std::uint8_t level[3];
  for (int k = 0; k < 3; ++k) level[k] = levelInBucket(t.buckets[index[k]], held[k]);
  return {level[0], level[1], level[2], static_cast<std::uint8_t>(alpha[3])};
#else
  (void)t;
  return encodePixel(glm::vec4(rgba[0], rgba[1], rgba[2], rgba[3]));
#endif
}

}  // namespace facet
