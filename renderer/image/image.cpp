#include "image/image.h"

#include "common/error.h"

namespace facet {

Image::Image(int width, int height, Rgba8 fill) : width_(width), height_(height) {
  if (width < 0 || height < 0) throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) + " is negative");
  pixels_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
}

}  // namespace facet
