#include "image/color_buffer.h"

#include <string>

#include "common/error.h"

namespace facet {

void ColorBuffer::reset(int width, int height, glm::vec4 fill) {
  resize(width, height);
  pixels_.assign(pixels_.size(), fill);
}

void ColorBuffer::resize(int width, int height) {
  if (width < 0 || height < 0) throw Error("colour buffer size " + std::to_string(width) + "x" + std::to_string(height) + " is negative");
  width_ = width;
  height_ = height;
  pixels_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
}

}  // namespace facet
