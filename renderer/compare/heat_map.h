#pragma once
// The difference of two images as a picture: black where they are equal,
// then the inferno ramp (color_ramp.h) by each pixel's largest channel
// difference, in two bands split at the fail threshold:
//   differences that pass (1 .. tolerated levels): the dark half, purple to
//     crimson, visible on black but quiet;
//   failing differences (above the fail threshold): the bright half, orange
//     to pale yellow, so they stand out at a glance.
// Within each band the position grows with the logarithm of the difference,
// so a 2-level change is still far from a 255-level one.
#include "compare/diff_thresholds.h"
#include "image/image.h"

namespace facet {

// The colour of a pixel whose largest channel difference is `levels` (0..255).
Rgba8 heatMapColor(int levels, const DiffThresholds& thresholds);

// Same-size images (throws facet::Error otherwise); opaque RGBA8, same size.
Image heatMap(const Image& expected, const Image& actual, const DiffThresholds& thresholds);

}  // namespace facet
