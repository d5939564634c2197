#pragma once
// The course's supersampling (renderer/PIPELINE.md, "Shading",
// "Anti-aliasing"): where in each pixel the samples lie, and the frame one
// sample is drawn with. Every backend draws the same passes, so the covered
// samples are the rasterizer's own rules at shifted positions.
#include <vector>

#include <glm/vec2.hpp>

#include "settings/render_settings.h"

namespace facet {

struct FrameInputs;

// The s × s sample offsets from the pixel centre, in pixels, each in
// [-0.5, 0.5): row by row from the bottom, left to right. grid: cell (i, j)'s
// centre ((i + 0.5)/s - 0.5, (j + 0.5)/s - 0.5); jittered: (i + u)/s - 0.5
// with u (and v) in [0, 1) from the seeded generator, k/2^24 for a 24-bit k,
// one pair per cell in that order. Each in double, rounded to float once.
std::vector<glm::vec2> sampleOffsets(int samplesPerSide, SamplePattern pattern, unsigned seed);

// `frame` drawn at the sample `offset` pixels from each pixel's centre: the
// projection PM' = T(-2·dx/W, -2·dy/H, 0)·PM moves window position p of the
// frame to p - offset, so that the centre of pixel (px, py) covers what lies
// at (px + 0.5, py + 0.5) + offset; the background's view directions follow
// (FrameInputs::sampleOffset).
FrameInputs sampleFrame(const FrameInputs& frame, glm::vec2 offset);

}  // namespace facet
