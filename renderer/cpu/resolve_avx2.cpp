// The resolve's encode on eight lanes, two pixels a register: the steps of
// encodePixel4 (srgb_table.h) with the bucket and threshold look-ups as
// gathers. Built with -mavx2 alone, under the rule of phong_batch_avx2.cpp:
// one flattened entry point, no other symbol (the test cpu.avx2_symbols).
#include <cstddef>
#include <immintrin.h>

#include "cpu/srgb_table.h"

#if !defined(__AVX2__)
#error "resolve_avx2.cpp is built with -mavx2"
#endif

namespace facet::cpu {

// The bucket gather reads four bytes at each bucket's level and keeps the
// first: the last bucket's read ends three bytes past the table, inside the
// struct (its padding) only if the table is its last member with room after.
static_assert(offsetof(SrgbTables, buckets) + kSrgbBuckets + 3 <= sizeof(SrgbTables), "the bucket gather's last read leaves SrgbTables");

__attribute__((flatten)) void encodePixelsEightLanes(const SrgbTables& t, const float* rgba, Rgba8* out, std::size_t count) {
  const auto* buckets = reinterpret_cast<const int*>(t.buckets.data());
  const __m256 one = _mm256_set1_ps(1.0f), zero = _mm256_setzero_ps();
  // Two pixels' four channels: the clamp, the level of R, G, B by the tables and A's linear level.
  const auto levels = [&](const float* pixels) {
    const __m256 x = _mm256_loadu_ps(pixels);
    const __m256 c = _mm256_and_ps(_mm256_cmp_ps(x, zero, _CMP_GT_OS), _mm256_min_ps(x, one));  // clampUnit, as minps then the mask
    const __m256i bucket = _mm256_srli_epi32(_mm256_castps_si256(c), kSrgbBucketShift);
    const __m256i start = _mm256_and_si256(_mm256_i32gather_epi32(buckets, bucket, 1), _mm256_set1_epi32(0xFF));
    const __m256 above = _mm256_i32gather_ps(t.thresholds.data() + 1, start, 4);  // thresholds[start + 1]
    const __m256i level = _mm256_sub_epi32(start, _mm256_castps_si256(_mm256_cmp_ps(above, c, _CMP_LE_OS)));  // + 1 where it is ≤ c
    const __m256i alpha = _mm256_cvttps_epi32(_mm256_add_ps(_mm256_mul_ps(c, _mm256_set1_ps(255.0f)), _mm256_set1_ps(0.5f)));
    return _mm256_blend_epi32(level, alpha, 0x88);  // lanes 3 and 7: alpha
  };
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {  // four pixels: two registers packed to 16 bytes
    const __m256i words = _mm256_packus_epi32(levels(rgba + 4 * i), levels(rgba + 4 * i + 8));  // per half: pixel 0|2, then 1|3
    const __m256i bytes = _mm256_packus_epi16(words, words);
    const __m256i ordered = _mm256_permutevar8x32_epi32(bytes, _mm256_setr_epi32(0, 4, 1, 5, 0, 0, 0, 0));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), _mm256_castsi256_si128(ordered));
  }
  for (; i < count; ++i) out[i] = encodePixel4(t, rgba + 4 * i);
}

}  // namespace facet::cpu
