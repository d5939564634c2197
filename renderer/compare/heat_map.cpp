#include "compare/heat_map.h"

#include <array>
#include <cmath>
#include <string>

#include "common/error.h"
#include "compare/color_ramp.h"
#include "compare/image_diff.h"

namespace facet {
namespace {

// Where each band sits on the ramp. The gap between them makes the step
// from passing to failing visible even when they differ by one level.
constexpr double kPassLow = 0.22, kPassHigh = 0.50;  // purple .. crimson
constexpr double kFailLow = 0.62, kFailHigh = 1.00;  // orange .. pale yellow

// 0 at `from`, 1 at `to`, logarithmic in between (from <= value <= to);
// 1 when the band holds a single value.
double logPosition(int value, int from, int to) {
  if (to <= from) return 1.0;
  return std::log1p(value - from) / std::log1p(to - from);
}

}  // namespace

Rgba8 heatMapColor(int levels, const DiffThresholds& thresholds) {
  if (levels <= 0) return {0, 0, 0, 255};
  const int tolerated = toleratedLevels(thresholds.failThreshold);
  if (levels <= tolerated) return inferno(kPassLow + (kPassHigh - kPassLow) * logPosition(levels, 1, tolerated));
  return inferno(kFailLow + (kFailHigh - kFailLow) * logPosition(levels, tolerated + 1, 255));
}

Image heatMap(const Image& expected, const Image& actual, const DiffThresholds& thresholds) {
  if (expected.width() != actual.width() || expected.height() != actual.height())
    throw Error("heat map: images of different sizes: " + std::to_string(expected.width()) + "x" + std::to_string(expected.height()) +
                " and " + std::to_string(actual.width()) + "x" + std::to_string(actual.height()));
  // One colour per possible difference, computed once.
  std::array<Rgba8, 256> colors{};
  for (int d = 0; d < 256; ++d) colors[static_cast<std::size_t>(d)] = heatMapColor(d, thresholds);
  Image out(expected.width(), expected.height());
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) out.at(x, y) = colors[static_cast<std::size_t>(pixelDifference(expected.at(x, y), actual.at(x, y)))];
  return out;
}

}  // namespace facet
