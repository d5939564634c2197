#include "compare/image_diff.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "common/error.h"

namespace facet {
namespace {

std::string sizeText(const Image& image) { return std::to_string(image.width()) + "x" + std::to_string(image.height()); }

// idiff's rule: more than `percent` of the pixels over the threshold, or any
// channel over the hard limit. Compared as counts x 100 so that 1 pixel in
// 100 against 1% stays exact.
bool exceeds(std::int64_t pixelsOver, double percent, int maxDifference, double hardLimit, std::int64_t pixelCount) {
  const bool tooMany = static_cast<double>(pixelsOver) * 100.0 > percent * static_cast<double>(pixelCount);
  const bool hardOver = hardLimit != kNoLimit && maxDifference > toleratedLevels(hardLimit);
  return tooMany || hardOver;
}

}  // namespace

int pixelDifference(Rgba8 e, Rgba8 a) {
  return std::max({std::abs(e.r - a.r), std::abs(e.g - a.g), std::abs(e.b - a.b), std::abs(e.a - a.a)});
}

DiffResult compareImages(const Image& expected, const Image& actual, const DiffThresholds& thresholds) {
  if (expected.width() != actual.width() || expected.height() != actual.height())
    throw Error("images of different sizes cannot be compared: expected " + sizeText(expected) + ", actual " + sizeText(actual));
  checkThresholds(thresholds);
  const int failLevels = toleratedLevels(thresholds.failThreshold);
  const int warnLevels = toleratedLevels(thresholds.warnThreshold);

  DiffResult r;
  r.width = expected.width();
  r.height = expected.height();
  std::array<std::int64_t, 4> sums{};  // of absolute differences per channel
  std::int64_t sumSquaresRgb = 0;
  int worstRgbSum = -1;
  for (int y = 0; y < r.height; ++y) {
    for (int x = 0; x < r.width; ++x) {
      const Rgba8 e = expected.at(x, y), a = actual.at(x, y);
      const std::array<int, 4> d = {std::abs(e.r - a.r), std::abs(e.g - a.g), std::abs(e.b - a.b), std::abs(e.a - a.a)};
      for (std::size_t c = 0; c < 4; ++c) {
        sums[c] += d[c];
        r.channels[c].max = std::max(r.channels[c].max, d[c]);
      }
      sumSquaresRgb += d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const int largest = std::max({d[0], d[1], d[2], d[3]});
      if (largest == 0) continue;
      ++r.differingPixels;
      r.differing.add(x, y);
      if (largest > failLevels) {
        ++r.failingPixels;
        r.failing.add(x, y);
      }
      if (largest > warnLevels) ++r.warningPixels;
      // Ties go to the larger colour change, then to the first pixel met.
      const int rgbSum = d[0] + d[1] + d[2];
      if (largest > r.worst.difference || (largest == r.worst.difference && rgbSum > worstRgbSum)) {
        r.worst = {x, y, largest, e, a};
        worstRgbSum = rgbSum;
      }
    }
  }

  const std::int64_t n = r.pixelCount();
  if (n == 0) return r;
  const double count = static_cast<double>(n);
  for (std::size_t c = 0; c < 4; ++c) {
    r.channels[c].mean = static_cast<double>(sums[c]) / count;
    r.maxDifference = std::max(r.maxDifference, r.channels[c].max);
  }
  r.rmse = std::sqrt(static_cast<double>(sumSquaresRgb) / (3.0 * count));
  if (r.rmse > 0.0) r.psnr = 20.0 * std::log10(255.0 / r.rmse);
  r.failingPercent = 100.0 * static_cast<double>(r.failingPixels) / count;
  r.warningPercent = 100.0 * static_cast<double>(r.warningPixels) / count;

  if (exceeds(r.failingPixels, thresholds.failPercent, r.maxDifference, thresholds.hardFail, n)) r.status = DiffStatus::Fail;
  else if (exceeds(r.warningPixels, thresholds.warnPercent, r.maxDifference, thresholds.hardWarn, n)) r.status = DiffStatus::Warn;
  return r;
}

}  // namespace facet
