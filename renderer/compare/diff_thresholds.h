#pragma once
// When two images count as the same, after OpenImageIO's idiff. Every
// threshold is a fraction of full scale (0..1, so one 8-bit step is
// 1/255 = 0.0039216) and applies to one channel of one pixel; a pixel is
// over a threshold when any of its four channels (R, G, B, A) differs by
// more than it. Percents are of all pixels, 0..100.
//
//   Pass: allowFailures is set (above 0) and at most that many pixels are
//         over failThreshold: they may fail by any amount.
//   Fail: otherwise, more than failPercent of pixels are over failThreshold,
//         or any channel anywhere differs by more than hardFail.
//   Warn: not Fail, and the same test with the warn values is true.
//   Pass: none of these.
#include <cstdint>
#include <limits>

namespace facet {

inline constexpr double kNoLimit = std::numeric_limits<double>::infinity();

// The defaults are idiff's, so that `facet diff a.png b.png` gives the
// verdict `idiff a.png b.png` gives: any difference at all fails (1e-6 is
// below one 8-bit step).
struct DiffThresholds {
  double failThreshold = 1e-6;       // fraction of full scale
  double failPercent = 0.0;          // percent of pixels allowed over failThreshold
  double hardFail = kNoLimit;        // fraction of full scale; kNoLimit: off
  std::int64_t allowFailures = 0;    // pixels that may fail by any amount; 0: off
  double warnThreshold = 1e-6;       // fraction of full scale
  double warnPercent = 0.0;          // percent of pixels allowed over warnThreshold
  double hardWarn = kNoLimit;        // fraction of full scale; kNoLimit: off
};

// Throws facet::Error naming the first value that is negative or not a
// number, or a percent above 100.
void checkThresholds(const DiffThresholds& thresholds);

// The largest 8-bit channel difference (0..255) that is not more than
// `fraction` of full scale: 1/255 gives 1, 0.004 gives 1, 0 gives 0, kNoLimit
// gives 255. A difference d is over the threshold exactly when d > this.
// idiff subtracts 32-bit floats, so a difference of exactly N levels lands
// a few float steps either side of N/255 and, at a threshold of N/255, is
// over it for some pixel values and not others; here it never is.
int toleratedLevels(double fraction);

}  // namespace facet
