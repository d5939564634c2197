#include "cpu/srgb_table.h"

#include <array>
#include <algorithm>
#include <bit>
#include <limits>
#include <stdexcept>

#include "cpu/lighting.h"
#include "cpu/texture_sampling.h"

namespace facet::cpu {
namespace {

unsigned levelOf(float c) { return quantize(encodeSrgb(glm::vec3(c)).r); }

}  // namespace

SrgbTable::SrgbTable() {
  threshold_[0] = -std::numeric_limits<float>::infinity();
  // Non-negative floats order as their bit patterns: bisect on those in [0, 1].
  const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
  for (unsigned k = 1; k < 256; ++k) {
    std::uint32_t lo = 0, hi = one;  // levelOf(hi) ≥ k always holds (levelOf(1) = 255)
    if (levelOf(0.0f) >= k) hi = 0;
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (levelOf(std::bit_cast<float>(mid)) >= k) hi = mid;
      else lo = mid + 1;
    }
    threshold_[k] = std::bit_cast<float>(hi);
  }
  threshold_[256] = std::numeric_limits<float>::infinity();
  // The level of c is the largest k with threshold_[k] <= c (levels never
  // decrease with c), so the buckets follow from the thresholds, in one walk.
  unsigned start = 0;
  for (std::uint32_t b = 0; b < kBuckets; ++b) {
    const float first = std::bit_cast<float>(b << kBucketShift);
    const float last = std::bit_cast<float>(std::min((b << kBucketShift) + ((1u << kBucketShift) - 1), one));
    while (threshold_[start + 1] <= first) ++start;
    if (start + 2 <= 256 && threshold_[start + 2] <= last) throw std::logic_error("sRGB table: two thresholds in one bucket");
    start_[b] = static_cast<std::uint8_t>(start);
  }
}

const SrgbTable& srgbTable() {
  static const SrgbTable table;
  return table;
}

const float* srgbDecodeTable() {
  static const auto table = [] {
    std::array<float, 256> t{};
    for (int v = 0; v < 256; ++v) t[static_cast<std::size_t>(v)] = decodeSrgb(glm::vec3(static_cast<float>(v)) / 255.0f).r;
    return t;
  }();
  return table.data();
}

}  // namespace facet::cpu
