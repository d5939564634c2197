#pragma once
// The depth-complexity view (renderer/PIPELINE.md, "Depth
// complexity"): FrameOutput::FragmentCounts as figures and as an image, so that
// a student sees why the z-buffer's cost follows the projected area drawn,
// not the pixels shown.
#include <cstdint>
#include <vector>

#include "image/image.h"

namespace facet {

struct DepthComplexity {
  std::uint32_t max = 0;          // fragments at the busiest pixel
  std::uint64_t fragments = 0;    // over the frame
  std::uint64_t covered = 0;      // pixels that received at least one
  double meanPerCovered() const { return covered ? static_cast<double>(fragments) / static_cast<double>(covered) : 0.0; }
};

DepthComplexity depthComplexityOf(const std::vector<std::uint32_t>& counts);

// Each pixel's count n as inferno(n / max): black where nothing was drawn,
// pale yellow at the busiest pixel; bottom row first, as the counts are.
Image depthComplexityImage(const std::vector<std::uint32_t>& counts, int width, int height);

}  // namespace facet
