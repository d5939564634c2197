#pragma once
// compareImages: every figure of how two images differ, and whether that
// passes, warns or fails under the thresholds (see diff_thresholds.h).
#include "compare/diff_result.h"
#include "compare/diff_thresholds.h"
#include "image/image.h"
#include "image/stored_channels.h"

namespace facet {

// The images must have the same size (throws facet::Error naming both
// sizes otherwise), as must be thresholds (checkThresholds). `channels`:
// those the mean error, RMSE and PSNR average over, the ones the two files
// store (unionOf); RGBA, facet's own images, by default.
DiffResult compareImages(const Image& expected, const Image& actual, const DiffThresholds& thresholds, StoredChannels channels = {});

// The largest of the four channel differences of one pixel, 8-bit levels.
int pixelDifference(Rgba8 expected, Rgba8 actual);

}  // namespace facet
