#include "image/image.h"

#include "common/error.h"

namespace facet {

namespace {

std::size_t pixelCount(int width, int height) {
  if (width < 0 || height < 0) throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) + " is negative");
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

}  // namespace

Image::Image(int width, int height, Rgba8 fill) : width_(width), height_(height) { pixels_.assign(pixelCount(width, height), fill); }

Image Image::unfilled(int width, int height) {
  Image image;
  image.resize(width, height);
  return image;
}

void Image::resize(int width, int height) {
  pixels_.resize(pixelCount(width, height));  // new pixels default-initialized: LargePageAllocator leaves them as handed over
  width_ = width, height_ = height;
}

}  // namespace facet
