#pragma once
// Where the lit pass draws one tile's colours: a window of the frame's
// linear colour buffer, or a tile-sized buffer of the worker's own that is
// resolved to the image as soon as the tile is drawn, while it is in the
// cache (a single-sample frame: the 33 MB float buffer then never reaches
// memory). Pixels are addressed by their frame coordinates either way.
#include <cstddef>

#include <glm/vec4.hpp>

#include "image/color_buffer.h"

namespace facet::cpu {

class TilePixels {
 public:
  // `first` holds pixel (x0, y0); a row is `stride` pixels after the one before.
  TilePixels(glm::vec4* first, std::size_t stride, int x0, int y0) : first_(first), stride_(stride), x0_(x0), y0_(y0) {}
  // The window of `buffer` whose first pixel is (x0, y0).
  static TilePixels of(ColorBuffer& buffer, int x0, int y0) {
    return {&buffer.at(x0, y0), static_cast<std::size_t>(buffer.width()), x0, y0};
  }

  glm::vec4& at(int px, int py) const { return first_[offset(px, py)]; }
  // Pixel (px, py)'s index from first(): px ≥ x0, py ≥ y0.
  std::size_t offset(int px, int py) const {
    return static_cast<std::size_t>(py - y0_) * stride_ + static_cast<std::size_t>(px - x0_);
  }
  glm::vec4* first() const { return first_; }

 private:
  glm::vec4* first_;
  std::size_t stride_;
  int x0_, y0_;
};

}  // namespace facet::cpu
