#pragma once
// encodeLevel (image/srgb.h) of four values: the clamp and the bucket index
// four at a time where SSE2 is there, then the same look-ups.
#include <cstdint>

#include "image/srgb.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace facet::cpu {

inline void encodeLevels4(const float* linear, std::uint8_t* out) {
#if defined(__SSE2__)
  const SrgbTables& t = srgbTables();
  const __m128 x = _mm_loadu_ps(linear);
  // (x < 1) ? x : 1 (minps), then 0 unless x > 0 (NaN too): clampUnit
  const __m128 c = _mm_and_ps(_mm_cmpgt_ps(x, _mm_setzero_ps()), _mm_min_ps(x, _mm_set1_ps(1.0f)));
  alignas(16) float clamped[4];
  alignas(16) std::uint32_t bucket[4];
  _mm_store_ps(clamped, c);
  _mm_store_si128(reinterpret_cast<__m128i*>(bucket), _mm_srli_epi32(_mm_castps_si128(c), kSrgbBucketShift));
  for (int k = 0; k < 4; ++k) {
    const unsigned start = t.buckets[bucket[k]];
    out[k] = static_cast<std::uint8_t>(start + (t.thresholds[start + 1] <= clamped[k] ? 1u : 0u));
  }
#else
  for (int k = 0; k < 4; ++k) out[k] = encodeLevel(linear[k]);
#endif
}

}  // namespace facet::cpu
