#include "compare/depth_complexity.h"

#include <algorithm>

#include "compare/color_ramp.h"

namespace facet {

DepthComplexity depthComplexityOf(const std::vector<std::uint32_t>& counts) {
  DepthComplexity d;
  for (const std::uint32_t n : counts) {
    d.max = std::max(d.max, n);
    d.fragments += n;
    d.covered += n > 0 ? 1 : 0;
  }
  return d;
}

Image depthComplexityImage(const std::vector<std::uint32_t>& counts, int width, int height) {
  const double max = std::max<std::uint32_t>(depthComplexityOf(counts).max, 1);
  Image image(width, height, inferno(0.0));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.at(x, y) = inferno(counts[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] / max);
  return image;
}

}  // namespace facet
