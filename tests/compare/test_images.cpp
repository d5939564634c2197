#include "test_images.h"

#include <algorithm>

namespace facet::test {

Image withPixel(Image image, int x, int y, Rgba8 color) {
  image.at(x, y) = color;
  return image;
}

Image shifted(Image image, int levels) {
  const auto add = [levels](std::uint8_t v) { return static_cast<std::uint8_t>(std::clamp(v + levels, 0, 255)); };
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      Rgba8& p = image.at(x, y);
      p = {add(p.r), add(p.g), add(p.b), p.a};
    }
  return image;
}

Image objectImage(int width, int height, int fromX, int toX) {
  Image image(width, height, kBlack);
  for (int y = 0; y < height; ++y)
    for (int x = fromX; x < toX; ++x) image.at(x, y) = kWhite;
  return image;
}

}  // namespace facet::test
