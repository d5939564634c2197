#pragma once
// The 8-bit sRGB level of a linear value (image/srgb.h: the count of the 255
// thresholds at or below it) in one table look-up and one comparison
// instead of a binary search: a second table, indexed by the exponent and
// top 8 mantissa bits of the clamped value, holds the level at the start of
// each such bucket, and no bucket holds more than one threshold (checked
// when the table is built). Equal to encodeLevel for every float in [0, 1]
// and outside (tests/cpu/test_fast_paths.cpp).
#include <bit>
#include <cstdint>

#include <glm/vec3.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "image/image.h"

namespace facet::cpu {

class SrgbTable {
 public:
  SrgbTable();
  // encodeLevel(linear), exactly.
  std::uint8_t encode(float linear) const {
    const float c = linear > 0.0f ? (linear < 1.0f ? linear : 1.0f) : 0.0f;  // NaN and below 0: level 0; above 1: 255
    return level(c, std::bit_cast<std::uint32_t>(c) >> kBucketShift);
  }
  Rgba8 pixel(glm::vec3 linear) const { return {encode(linear.r), encode(linear.g), encode(linear.b), 255}; }
  // encode() of four values; the clamp and the bucket index four at a time where SSE2 is there.
  void encode4(const float* linear, std::uint8_t* out) const {
#if defined(__SSE2__)
    const __m128 x = _mm_loadu_ps(linear);
    // (x < 1) ? x : 1 (minps), then 0 unless x > 0 (NaN too): encode()'s clamp
    const __m128 c = _mm_and_ps(_mm_cmpgt_ps(x, _mm_setzero_ps()), _mm_min_ps(x, _mm_set1_ps(1.0f)));
    alignas(16) float clamped[4];
    alignas(16) std::uint32_t bucket[4];
    _mm_store_ps(clamped, c);
    _mm_store_si128(reinterpret_cast<__m128i*>(bucket), _mm_srli_epi32(_mm_castps_si128(c), kBucketShift));
    for (int k = 0; k < 4; ++k) out[k] = level(clamped[k], bucket[k]);
#else
    for (int k = 0; k < 4; ++k) out[k] = encode(linear[k]);
#endif
  }

 private:
  static constexpr int kBucketShift = 15;  // keeps the sign, the exponent and 8 mantissa bits
  static constexpr std::uint32_t kBuckets = (std::bit_cast<std::uint32_t>(1.0f) >> kBucketShift) + 1;  // every c in [0, 1]

  // The level of clamped c in `bucket` (its bits >> kBucketShift): the bucket's start, plus one past its threshold.
  std::uint8_t level(float c, std::uint32_t bucket) const {
    const unsigned start = start_[bucket];
    return static_cast<std::uint8_t>(start + (threshold_[start + 1] <= c ? 1u : 0u));
  }

  float threshold_[257];            // [k]: smallest c in [0,1] with level ≥ k; [0] = -inf, [256] = +inf
  std::uint8_t start_[kBuckets];    // level of the smallest float of each bucket (32 KB)
};

// The table, built on first use (thread-safe).
const SrgbTable& srgbTable();


}  // namespace facet::cpu
