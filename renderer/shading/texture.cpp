#include "shading/texture.h"

#include <algorithm>
#include <cmath>

#include "shading/shading_math.h"
#include "image/srgb.h"

namespace facet {
namespace {

// The texel (x, y), bottom row first: colour decoded to linear by the shared table (data: byte / 255), alpha as stored.
glm::vec4 texel(const Image& image, TexelEncoding encoding, int x, int y) {
  const Rgba8 c = image.at(x, y);
  if (encoding == TexelEncoding::Linear)
    return {static_cast<float>(c.r) / 255.0f, static_cast<float>(c.g) / 255.0f, static_cast<float>(c.b) / 255.0f, static_cast<float>(c.a) / 255.0f};
  const float* decoded = srgbTables().decoded.data();
  return {decoded[c.r], decoded[c.g], decoded[c.b], static_cast<float>(c.a) / 255.0f};
}

// floor(x) as a texel index: beyond ±2^24 every float is a whole number, and
// the clamp keeps the conversion defined without changing any texel inside.
int texelIndex(float x0) { return static_cast<int>(x0 < -16777216.0f ? -16777216.0f : (x0 > 16777216.0f ? 16777216.0f : x0)); }

bool linearWithin(MinFilter f) { return f == MinFilter::Linear || f == MinFilter::LinearMipmapNearest || f == MinFilter::LinearMipmapLinear; }

}  // namespace

int wrapIndex(int i, int size, Wrap mode) {
  if (mode == Wrap::ClampToEdge) return std::min(std::max(i, 0), size - 1);
  if (mode == Wrap::MirroredRepeat) {
    const int m = wrap(i, 2 * size);
    return m < size ? m : 2 * size - 1 - m;
  }
  return wrap(i, size);
}

glm::vec4 lerp(glm::vec4 a, glm::vec4 b, float t) { return a + t * (b - a); }

glm::vec4 sampleLevel(const Image& level, TexelEncoding encoding, bool linear, Wrap wrapS, Wrap wrapT, glm::vec2 st) {
  return sampleRegion(level, encoding, {0, 0}, {level.width(), level.height()}, linear, wrapS, wrapT, st);
}

glm::vec4 sampleRegion(const Image& image, TexelEncoding encoding, glm::ivec2 origin, glm::ivec2 size, bool linear, Wrap wrapS, Wrap wrapT,
                       glm::vec2 st) {
  const int w = size.x, h = size.y;
  const auto at = [&](int x, int y) { return texel(image, encoding, origin.x + x, origin.y + y); };
  const float u = st.x * static_cast<float>(w);
  const float v = (1.0f - st.y) * static_cast<float>(h);
  if (!linear) {
    if (!std::isfinite(u) || !std::isfinite(v)) return at(0, 0);
    return at(wrapIndex(texelIndex(std::floor(u)), w, wrapS), wrapIndex(texelIndex(std::floor(v)), h, wrapT));
  }
  const float x = u - 0.5f, y = v - 0.5f;
  if (!std::isfinite(x) || !std::isfinite(y)) return at(0, 0);
  const float x0 = std::floor(x), y0 = std::floor(y);
  const float fx = x - x0, fy = y - y0;
  const int ix = texelIndex(x0), iy = texelIndex(y0);
  const int ix0 = wrapIndex(ix, w, wrapS), ix1 = wrapIndex(ix + 1, w, wrapS);
  const int iy0 = wrapIndex(iy, h, wrapT), iy1 = wrapIndex(iy + 1, h, wrapT);
  const glm::vec4 c00 = at(ix0, iy0), c10 = at(ix1, iy0);
  const glm::vec4 c01 = at(ix0, iy1), c11 = at(ix1, iy1);
  return lerp(lerp(c00, c10, fx), lerp(c01, c11, fx), fy);
}

float footprintSquared(glm::vec4 d, int width, int height) {
  const float W = static_cast<float>(width), H = static_cast<float>(height);
  const float a = d.x * W, b = d.y * H, c = d.z * W, e = d.w * H;
  const float alongX = a * a + b * b, alongY = c * c + e * e;
  return alongX > alongY ? alongX : alongY;
}

glm::vec4 sampleTexture(const Texture& texture, const Sampler& sampler, glm::vec2 st, glm::vec4 derivatives) {
  const float rho2 = footprintSquared(derivatives, texture.image.width(), texture.image.height());
  if (!(rho2 > 1.0f)) return sampleLevel(texture.image, texture.encoding, sampler.mag == MagFilter::Linear, sampler.wrapS, sampler.wrapT, st);
  const bool linear = linearWithin(sampler.min);
  if (sampler.min == MinFilter::Nearest || sampler.min == MinFilter::Linear)
    return sampleLevel(texture.image, texture.encoding, linear, sampler.wrapS, sampler.wrapT, st);
  const float halfLog = 0.5f * log2Of(rho2);
  const float lambda = halfLog > 0.0f ? halfLog : 0.0f;
  const int last = texture.levelCount() - 1;
  if (sampler.min == MinFilter::NearestMipmapNearest || sampler.min == MinFilter::LinearMipmapNearest) {
    const float nearest = std::floor(lambda + 0.5f);
    const int k = nearest < static_cast<float>(last) ? static_cast<int>(nearest) : last;
    return sampleLevel(texture.level(k), texture.encoding, linear, sampler.wrapS, sampler.wrapT, st);
  }
  const float whole = std::floor(lambda);
  const int k = whole < static_cast<float>(last) ? static_cast<int>(whole) : last;
  const glm::vec4 above = sampleLevel(texture.level(k), texture.encoding, linear, sampler.wrapS, sampler.wrapT, st);
  if (k == last) return above;
  const glm::vec4 below = sampleLevel(texture.level(k + 1), texture.encoding, linear, sampler.wrapS, sampler.wrapT, st);
  return lerp(above, below, lambda - whole);
}

}  // namespace facet
