#pragma once
#include <cstdint>
#include <vector>

#include "common/large_pages.h"

namespace facet {

// An RGBA8 image. Rows are stored bottom row first, as OpenGL's window
// coordinates have their origin at the lower left; files are written top row
// first, so rows flip exactly once, in the PNG writer and reader.
// No default member initializers: a default-initialized Rgba8 is left as it
// is (Image::unfilled's storage); Rgba8{} is (0, 0, 0, 0).
struct Rgba8 {
  std::uint8_t r, g, b, a;
  friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

class Image {
 public:
  Image() = default;
  Image(int width, int height, Rgba8 fill = {});
  // An image whose every pixel the caller is about to write (a resolve): its
  // storage is not filled first, so the pages are first touched by the
  // writers, on their threads (the fill took 1.5 % of a sphere-100k frame
  // on one thread, and the kernel's page clearing another 1.8 %).
  static Image unfilled(int width, int height);
  // The size alone, as ColorBuffer::resize: the pixels keep what they held,
  // new ones are undefined, and the storage stays where it is large enough
  // (a recycled frame's image, Renderer::recycle). Throws facet::Error for a
  // negative size.
  void resize(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return width_ == 0 || height_ == 0; }

  // (x, y) with y = 0 at the bottom row.
  Rgba8& at(int x, int y) { return pixels_[index(x, y)]; }
  const Rgba8& at(int x, int y) const { return pixels_[index(x, y)]; }

  Rgba8* data() { return pixels_.data(); }
  const Rgba8* data() const { return pixels_.data(); }

  friend bool operator==(const Image&, const Image&) = default;

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x); }

  int width_ = 0;
  int height_ = 0;
  LargeVector<Rgba8> pixels_;
};

}  // namespace facet
