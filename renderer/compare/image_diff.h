#pragma once
// compareImages: every figure of how two images differ, and whether that
// passes, warns or fails under the thresholds (see diff_thresholds.h).
#include "compare/diff_result.h"
#include "compare/diff_thresholds.h"
#include "image/image.h"

namespace facet {

// The images must have the same size (throws facet::Error naming both
// sizes otherwise), as must be thresholds (checkThresholds).
DiffResult compareImages(const Image& expected, const Image& actual, const DiffThresholds& thresholds);

// The largest of the four channel differences of one pixel, 8-bit levels.
int pixelDifference(Rgba8 expected, Rgba8 actual);

}  // namespace facet
