#include "image/srgb.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace facet {
namespace {

// floor(255·E(c) + 0.5) for c in [0, 1], in double precision.
unsigned levelOf(float c) {
  const double x = c;
  const double encoded = x <= kSrgbLinearEnd ? kSrgbSlope * x : kSrgbScale * std::pow(x, 1.0 / kSrgbGamma) - kSrgbOffset;
  return static_cast<unsigned>(std::floor(255.0 * encoded + 0.5));
}

SrgbTables build() {
  SrgbTables t{};
  t.thresholds[0] = -std::numeric_limits<float>::infinity();
  t.thresholds[256] = std::numeric_limits<float>::infinity();
  // Non-negative floats order as their bit patterns: bisect on those in [0, 1].
  const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
  for (unsigned k = 1; k < 256; ++k) {
    std::uint32_t lo = 0, hi = one;  // levelOf(1) = 255 ≥ k
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (levelOf(std::bit_cast<float>(mid)) >= k) hi = mid;
      else lo = mid + 1;
    }
    t.thresholds[k] = std::bit_cast<float>(hi);
  }
  // The level of c is the largest k with thresholds[k] <= c, so the buckets
  // follow from the thresholds, in one walk.
  if (!(kSrgbFloor < t.thresholds[1])) throw std::logic_error("sRGB tables: level 1 starts below the buckets' floor");
  unsigned start = 0;
  for (std::uint32_t b = 0; b < kSrgbBuckets; ++b) {
    const std::uint32_t firstBits = (kSrgbFirstBucket + b) << kSrgbBucketShift;
    const float first = std::bit_cast<float>(firstBits);
    const float last = std::bit_cast<float>(std::min(firstBits + kSrgbInBucket, one));
    while (t.thresholds[start + 1] <= first) ++start;
    if (start + 2 <= 256 && t.thresholds[start + 2] <= last) throw std::logic_error("sRGB tables: two thresholds in one bucket");
    const float next = t.thresholds[start + 1];  // > first; +inf past level 255
    const std::uint32_t edge = next <= last ? std::bit_cast<std::uint32_t>(next) - firstBits : kSrgbInBucket + 1;  // in [1, 2^15]
    t.buckets[b] = start << kSrgbBucketShift | (kSrgbInBucket + 1 - edge);
  }
  for (unsigned v = 0; v < 256; ++v) {
    const double c = v / 255.0;
    t.decoded[v] = static_cast<float>(c <= 0.04045 ? c / kSrgbSlope : std::pow((c + kSrgbOffset) / kSrgbScale, kSrgbGamma));  // 0.04045 = E(kSrgbLinearEnd), as IEC writes it
  }
  return t;
}

}  // namespace

const SrgbTables& srgbTables() {
  static const SrgbTables tables = build();
  return tables;
}

std::uint8_t levelBySearch(float linear) {
  const SrgbTables& t = srgbTables();
  unsigned level = 0;
  for (unsigned step = 128; step > 0; step /= 2)
    if (t.thresholds[level + step] <= linear) level += step;
  return static_cast<std::uint8_t>(level);
}

}  // namespace facet
