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

DiffResult compareImages(const Image& expected, const Image& actual, const DiffThresholds& thresholds, StoredChannels channels) {
  if (expected.width() != actual.width() || expected.height() != actual.height())
    throw Error("images of different sizes cannot be compared: expected " + sizeText(expected) + ", actual " + sizeText(actual));
  checkThresholds(thresholds);
  const int failLevels = toleratedLevels(thresholds.failThreshold);
  const int warnLevels = toleratedLevels(thresholds.warnThreshold);

  DiffResult r;
  r.width = expected.width();
  r.height = expected.height();
  r.storedChannels = channels;
  std::array<std::int64_t, 4> sums{}, sumSquares{};  // per channel
  // Rows from the top, as idiff reads them: the first largest difference met
  // is the one it reports.
  for (int y = r.height - 1; y >= 0; --y) {
    for (int x = 0; x < r.width; ++x) {
      const Rgba8 e = expected.at(x, y), a = actual.at(x, y);
      const std::array<int, 4> d = {std::abs(e.r - a.r), std::abs(e.g - a.g), std::abs(e.b - a.b), std::abs(e.a - a.a)};
      int largest = 0;
      for (std::size_t c = 0; c < 4; ++c) {
        sums[c] += d[c];
        sumSquares[c] += d[c] * d[c];
        r.channels[c].max = std::max(r.channels[c].max, d[c]);
        largest = std::max(largest, d[c]);
        if (d[c] > r.worst.difference) r.worst = {x, y, static_cast<int>(c), d[c], e, a};
      }
      if (largest == 0) continue;
      ++r.differingPixels;
      r.differing.add(x, y);
      if (largest > failLevels) {
        ++r.failingPixels;
        r.failing.add(x, y);
      }
      if (largest > warnLevels) ++r.warningPixels;
    }
  }

  const std::int64_t n = r.pixelCount();
  if (n == 0) return r;
  const double count = static_cast<double>(n);
  for (std::size_t c = 0; c < 4; ++c) {
    r.channels[c].mean = static_cast<double>(sums[c]) / count;
    r.maxDifference = std::max(r.maxDifference, r.channels[c].max);
  }
  // A grey file's one channel is R (= G = B); alpha only when a file has it.
  std::int64_t sum = 0, sumSquare = 0;
  for (std::size_t c = 0; c < 4; ++c) {
    const bool stored = c == 0 || (c < 3 && channels.colour) || (c == 3 && channels.alpha);
    if (stored) {
      sum += sums[c];
      sumSquare += sumSquares[c];
    }
  }
  const double values = count * channels.count();
  r.meanError = static_cast<double>(sum) / values;
  r.rmse = std::sqrt(static_cast<double>(sumSquare) / values);
  if (r.rmse > 0.0) r.psnr = 20.0 * std::log10(255.0 / r.rmse);
  r.failingPercent = 100.0 * static_cast<double>(r.failingPixels) / count;
  r.warningPercent = 100.0 * static_cast<double>(r.warningPixels) / count;

  // idiff (2.4 and later) also passes when allowFailures is 0 and no pixel
  // fails, never warning then; its help, and idiff before 2.4, say that
  // only a limit the user sets lets failures through, as here.
  const bool allowed = thresholds.allowFailures > 0 && r.failingPixels <= thresholds.allowFailures;
  if (allowed) r.status = DiffStatus::Pass;
  else if (exceeds(r.failingPixels, thresholds.failPercent, r.maxDifference, thresholds.hardFail, n)) r.status = DiffStatus::Fail;
  else if (exceeds(r.warningPixels, thresholds.warnPercent, r.maxDifference, thresholds.hardWarn, n)) r.status = DiffStatus::Warn;
  return r;
}

}  // namespace facet
