#include "image/mipmap.h"

#include <algorithm>
#include <cmath>

#include "image/srgb.h"

namespace facet {
namespace {

// The texels of level k a texel i of level k+1 averages: [2i, 2i + 1], or to
// the last where i is the last and the size is odd.
struct Span {
  int first, last;
};
Span spanOf(int i, int size, int halfSize) {
  if (size == 1) return {0, 0};
  return {2 * i, i == halfSize - 1 ? size - 1 : 2 * i + 1};
}

Image halve(const Image& level, TexelEncoding encoding) {
  const int w = level.width(), h = level.height();
  const int hw = std::max(1, w / 2), hh = std::max(1, h / 2);
  const float* decoded = srgbTables().decoded.data();
  Image next(hw, hh);
  for (int j = 0; j < hh; ++j) {
    const Span rows = spanOf(j, h, hh);
    for (int i = 0; i < hw; ++i) {
      const Span columns = spanOf(i, w, hw);
      float r = 0, g = 0, b = 0, a = 0;
      for (int y = rows.first; y <= rows.last; ++y)
        for (int x = columns.first; x <= columns.last; ++x) {
          const Rgba8 c = level.at(x, y);
          if (encoding == TexelEncoding::Srgb) r += decoded[c.r], g += decoded[c.g], b += decoded[c.b];
          else r += static_cast<float>(c.r), g += static_cast<float>(c.g), b += static_cast<float>(c.b);
          a += static_cast<float>(c.a);
        }
      const float n = static_cast<float>((rows.last - rows.first + 1) * (columns.last - columns.first + 1));
      const auto byte = [](float v) { return static_cast<std::uint8_t>(std::lround(v)); };
      next.at(i, j) = encoding == TexelEncoding::Srgb ? Rgba8{encodeLevel(r / n), encodeLevel(g / n), encodeLevel(b / n), byte(a / n)}
                                                      : Rgba8{byte(r / n), byte(g / n), byte(b / n), byte(a / n)};
    }
  }
  return next;
}

}  // namespace

int mipLevelCount(int width, int height) {
  int count = 0;
  for (int side = std::max(width, height); side > 1; side /= 2) ++count;
  return count;
}

std::uint64_t mipChainPixels(int width, int height) {
  std::uint64_t pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  for (int k = 0, count = mipLevelCount(width, height); k < count; ++k) {
    width = std::max(1, width / 2), height = std::max(1, height / 2);
    pixels += static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  }
  return pixels;
}

std::vector<Image> mipLevels(const Image& image, TexelEncoding encoding) {
  std::vector<Image> levels;
  if (image.empty()) return levels;
  levels.reserve(static_cast<std::size_t>(mipLevelCount(image.width(), image.height())));
  for (int k = 0, count = mipLevelCount(image.width(), image.height()); k < count; ++k) levels.push_back(halve(k == 0 ? image : levels.back(), encoding));
  return levels;
}

}  // namespace facet
