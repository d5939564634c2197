#include "cpu/srgb_table.h"

#include <array>
#include <algorithm>
#include <bit>
#include <limits>
#include <stdexcept>

#include "image/srgb.h"

namespace facet::cpu {

SrgbTable::SrgbTable() {
  const std::array<float, 256>& thresholds = srgbTables().thresholds;
  std::copy(thresholds.begin(), thresholds.end(), threshold_);
  threshold_[256] = std::numeric_limits<float>::infinity();
  const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
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

}  // namespace facet::cpu
