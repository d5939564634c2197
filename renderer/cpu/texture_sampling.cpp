#include "cpu/texture_sampling.h"

#include <cmath>

#include <glm/common.hpp>

#include "cpu/srgb_table.h"

namespace facet::cpu {
namespace {

int wrap(int i, int size) { return ((i % size) + size) % size; }

// decodeSrgb(glm::vec3(c.r, c.g, c.b) / 255.0f), by a table of the 256 values per channel.
glm::vec3 texel(const Image& image, int x, int y) {
  static const float* const decoded = srgbDecodeTable();
  const Rgba8 c = image.at(x, y);
  return {decoded[c.r], decoded[c.g], decoded[c.b]};
}

}  // namespace

glm::vec3 lerp(glm::vec3 a, glm::vec3 b, float t) { return a + t * (b - a); }

glm::vec3 decodeSrgb(glm::vec3 c) {
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = c[i] <= 0.04045f ? c[i] / 12.92f : std::pow((c[i] + 0.055f) / 1.055f, 2.4f);
  return out;
}

glm::vec3 sampleBaseColor(const Image& image, glm::vec2 st) {
  const int w = image.width(), h = image.height();
  const float x = st.x * static_cast<float>(w) - 0.5f;
  const float y = (1.0f - st.y) * static_cast<float>(h) - 0.5f;
  if (!std::isfinite(x) || !std::isfinite(y)) return texel(image, 0, 0);
  const float x0 = std::floor(x), y0 = std::floor(y);
  const float fx = x - x0, fy = y - y0;
  // Coordinates far outside [0,1] still wrap: reduce before converting to int, which could overflow.
  const int ix = static_cast<int>(std::fmod(x0, static_cast<float>(w))), iy = static_cast<int>(std::fmod(y0, static_cast<float>(h)));
  const int ix0 = wrap(ix, w), ix1 = wrap(ix + 1, w), iy0 = wrap(iy, h), iy1 = wrap(iy + 1, h);
  const glm::vec3 c00 = texel(image, ix0, iy0), c10 = texel(image, ix1, iy0);
  const glm::vec3 c01 = texel(image, ix0, iy1), c11 = texel(image, ix1, iy1);
  return lerp(lerp(c00, c10, fx), lerp(c01, c11, fx), fy);
}

}  // namespace facet::cpu
