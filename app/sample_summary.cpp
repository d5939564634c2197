#include "sample_summary.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace facet {

double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0;
  const double at = q * static_cast<double>(sorted.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(at)), hi = static_cast<std::size_t>(std::ceil(at));
  return sorted[lo] + (sorted[hi] - sorted[lo]) * (at - static_cast<double>(lo));
}

Summary summarize(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  if (values.empty()) return {};
  return {quantile(values, 0.5), values.front(), values.back(), quantile(values, 0.25), quantile(values, 0.75)};
}

}  // namespace facet
