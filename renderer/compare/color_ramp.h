#pragma once
// A perceptually ordered colour ramp for heat maps.
#include "image/image.h"

namespace facet {

// Matplotlib's "inferno" (van der Walt and Smith, CC0): black through purple,
// red and orange to pale yellow, its lightness rising evenly with t, so
// larger values always look brighter, in colour and in grey. t in [0, 1]
// (clamped); alpha is 255.
Rgba8 inferno(double t);

}  // namespace facet
