#pragma once
// When two images count as the same, after OpenImageIO's idiff. Every
// threshold is a fraction of full scale (0..1, so one 8-bit step is
// 1/255 = 0.0039216) and applies to one channel of one pixel; a pixel is
// over a threshold when any of its four channels (R, G, B, A) differs by
// more than it. Percents are of all pixels, 0..100.
//
//   Fail: more than failPercent of pixels are over failThreshold, or any
//         channel anywhere differs by more than hardFail.
//   Warn: not Fail, and the same test with the warn values is true.
//   Pass: neither.
#include <limits>

namespace facet {

inline constexpr double kNoLimit = std::numeric_limits<double>::infinity();

struct DiffThresholds {
  // One 8-bit step passes (with a warning): each backend rounds its colours
  // to 8 bits on its own, so a value that lands near a step boundary may
  // round either way. Two steps is a real difference.
  double failThreshold = 1.0 / 255.0;  // fraction of full scale
  double failPercent = 0.0;            // percent of pixels allowed over failThreshold
  double hardFail = kNoLimit;          // fraction of full scale; kNoLimit: off
  // Any difference at all warns, so an off-by-one is seen without failing.
  double warnThreshold = 0.0;          // fraction of full scale
  double warnPercent = 0.0;            // percent of pixels allowed over warnThreshold
  double hardWarn = kNoLimit;          // fraction of full scale; kNoLimit: off
};

// Throws facet::Error naming the first value that is negative or not a
// number, or a percent above 100.
void checkThresholds(const DiffThresholds& thresholds);

// The largest 8-bit channel difference (0..255) that is not more than
// `fraction` of full scale: 1/255 gives 1, 0.004 gives 1, 0 gives 0, kNoLimit
// gives 255. A difference d is over the threshold exactly when d > this.
int toleratedLevels(double fraction);

}  // namespace facet
