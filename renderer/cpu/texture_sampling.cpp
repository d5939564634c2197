#include "cpu/texture_sampling.h"

#include <cmath>

#include "image/srgb.h"

namespace facet::cpu {
namespace {

// The texel (x, y), bottom row first, decoded to linear by the shared table.
glm::vec3 texel(const Image& image, int x, int y) {
  const float* decoded = srgbTables().decoded.data();
  const Rgba8 c = image.at(x, y);
  return {decoded[c.r], decoded[c.g], decoded[c.b]};
}

// floor(x) as a texel index: beyond ±2^24 every float is a whole number, and
// the clamp keeps the conversion defined without changing any texel inside.
int texelIndex(float x0) { return static_cast<int>(x0 < -16777216.0f ? -16777216.0f : (x0 > 16777216.0f ? 16777216.0f : x0)); }

}  // namespace

glm::vec3 lerp(glm::vec3 a, glm::vec3 b, float t) { return a + t * (b - a); }

glm::vec3 sampleBaseColor(const Image& image, glm::vec2 st) {
  const int w = image.width(), h = image.height();
  const float x = st.x * static_cast<float>(w) - 0.5f;
  const float y = (1.0f - st.y) * static_cast<float>(h) - 0.5f;
  if (!std::isfinite(x) || !std::isfinite(y)) return texel(image, 0, 0);
  const float x0 = std::floor(x), y0 = std::floor(y);
  const float fx = x - x0, fy = y - y0;
  const int ix = texelIndex(x0), iy = texelIndex(y0);
  const int ix0 = wrap(ix, w), ix1 = wrap(ix + 1, w), iy0 = wrap(iy, h), iy1 = wrap(iy + 1, h);
  const glm::vec3 c00 = texel(image, ix0, iy0), c10 = texel(image, ix1, iy0);
  const glm::vec3 c01 = texel(image, ix0, iy1), c11 = texel(image, ix1, iy1);
  return lerp(lerp(c00, c10, fx), lerp(c01, c11, fx), fy);
}

}  // namespace facet::cpu
