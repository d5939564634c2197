#pragma once
// The lit pass's colour buffer: linear RGBA in 32-bit float, rows bottom
// first as in facet::Image. Colours are combined here (blended, averaged
// over samples) before the resolve encodes them once (renderer/PIPELINE.md,
// "The colour buffer and the resolve").
#include <cstddef>
#include <vector>

#include <glm/vec4.hpp>

#include "common/large_pages.h"

namespace facet {

class ColorBuffer {
 public:
  ColorBuffer() = default;
  // Every pixel set to `fill`; throws facet::Error for a negative size.
  ColorBuffer(int width, int height, glm::vec4 fill) { reset(width, height, fill); }
  // The same, keeping the memory it has: a renderer's buffer is reused from frame to frame.
  void reset(int width, int height, glm::vec4 fill);
  // The size alone: the pixels keep what they held, new ones are undefined (for a caller
  // that writes every pixel next, on its threads).
  void resize(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  // (x, y) with y = 0 at the bottom row.
  glm::vec4& at(int x, int y) { return pixels_[index(x, y)]; }
  const glm::vec4& at(int x, int y) const { return pixels_[index(x, y)]; }

  glm::vec4* data() { return pixels_.data(); }
  const glm::vec4* data() const { return pixels_.data(); }

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x); }

  int width_ = 0;
  int height_ = 0;
  LargeVector<glm::vec4> pixels_;
};

}  // namespace facet
