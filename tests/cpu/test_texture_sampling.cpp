// Texture mapping's rules (renderer/PIPELINE.md, "Textures"): mipmaps in
// linear light, the three wraps, the level of detail and each filter.
#include <cmath>
#include <limits>

#include <doctest/doctest.h>

#include "shading/texture.h"
#include "image/mipmap.h"
#include "image/srgb.h"
#include "pipeline/material_coefficients.h"

using namespace facet;

namespace {

float linear(std::uint8_t v) { return srgbTables().decoded[v]; }

Image solid(int w, int h, std::uint8_t grey) { return Image(w, h, {grey, grey, grey, 255}); }

// A 16x16 texture whose levels are solid greys 200, 160, 120, 80, 40 (levels 0..4), to see which level a lookup reads.
Texture levelledTexture() {
  Texture t;
  t.image = solid(16, 16, 200);
  for (int k = 1; k <= 4; ++k) t.mips.push_back(solid(16 >> k, 16 >> k, static_cast<std::uint8_t>(200 - 40 * k)));
  return t;
}

// Derivatives whose footprint is rho level-0 texels along x.
glm::vec4 footprint(float rho) { return {rho / 16.0f, 0.0f, 0.0f, 0.0f}; }

Sampler withMin(MinFilter min) {
  Sampler s;
  s.min = min;
  return s;
}

}  // namespace

TEST_CASE("mipmaps: each level halves the one above, box-averaged in linear light, odd sizes folding their last texel in") {
  // Black and white columns average to linear 0.5, which is byte 188 (not 128: the average is in linear light).
  Image stripes(4, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) stripes.at(x, y) = x % 2 ? Rgba8{255, 255, 255, 255} : Rgba8{0, 0, 0, 0};
  const std::vector<Image> levels = mipLevels(stripes, TexelEncoding::Srgb);
  REQUIRE(levels.size() == 2);
  CHECK(levels[0].width() == 2);
  CHECK(levels[0].height() == 1);
  CHECK(levels[1].width() == 1);
  CHECK(levels[1].height() == 1);
  CHECK(levels[0].at(0, 0) == Rgba8{encodeLevel(0.5f), encodeLevel(0.5f), encodeLevel(0.5f), 128});
  CHECK(encodeLevel(0.5f) == 188);
  // 3x1: the one texel of level 1 averages all three (2/3 white), not the first two.
  Image odd(3, 1);
  odd.at(0, 0) = {0, 0, 0, 255}, odd.at(1, 0) = {255, 255, 255, 255}, odd.at(2, 0) = {255, 255, 255, 255};
  const std::vector<Image> oddLevels = mipLevels(odd, TexelEncoding::Srgb);
  REQUIRE(oddLevels.size() == 1);
  CHECK(oddLevels[0].at(0, 0).r == encodeLevel(2.0f / 3.0f));
  CHECK(mipLevelCount(1, 1) == 0);
  CHECK(mipLevelCount(300, 7) == 8);
  CHECK(mipChainPixels(4, 2) == 8 + 2 + 1);
  CHECK(mipChainPixels(8192, 8192) == 89478485);  // (4^14 - 1)/3
}

TEST_CASE("wraps: REPEAT, CLAMP_TO_EDGE and MIRRORED_REPEAT map every index into the axis") {
  CHECK(wrapIndex(-1, 4, Wrap::Repeat) == 3);
  CHECK(wrapIndex(9, 4, Wrap::Repeat) == 1);
  CHECK(wrapIndex(-1, 4, Wrap::ClampToEdge) == 0);
  CHECK(wrapIndex(9, 4, Wrap::ClampToEdge) == 3);
  // Mirrored: 0 1 2 3 | 3 2 1 0 | 0 1 2 3, and to the left 0 | 0 1 2 3.
  const int mirrored[] = {0, 1, 2, 3, 3, 2, 1, 0, 0, 1};
  for (int i = 0; i < 10; ++i) CHECK(wrapIndex(i, 4, Wrap::MirroredRepeat) == mirrored[i]);
  CHECK(wrapIndex(-1, 4, Wrap::MirroredRepeat) == 0);
  CHECK(wrapIndex(-5, 4, Wrap::MirroredRepeat) == 3);
  CHECK(wrapIndex(-2147483647, 5, Wrap::MirroredRepeat) >= 0);
}

TEST_CASE("level of detail: magnification reads level 0, minification the level log2(rho) names, by each min filter") {
  const Texture t = levelledTexture();
  const glm::vec2 st{0.3f, 0.6f};
  const auto read = [&](MinFilter min, float rho) { return sampleTexture(t, withMin(min), st, footprint(rho)).r; };
  // rho <= 1 magnifies, whatever the min filter.
  CHECK(read(MinFilter::LinearMipmapLinear, 1.0f) == linear(200));
  CHECK(read(MinFilter::NearestMipmapNearest, 0.25f) == linear(200));
  // NEAREST and LINEAR have no mipmaps.
  CHECK(read(MinFilter::Linear, 8.0f) == linear(200));
  CHECK(read(MinFilter::Nearest, 8.0f) == linear(200));
  // rho = 4: lambda = 2.
  CHECK(read(MinFilter::NearestMipmapNearest, 4.0f) == linear(120));
  CHECK(read(MinFilter::LinearMipmapLinear, 4.0f) == doctest::Approx(linear(120)).epsilon(1e-5));
  // rho = 2^1.75: nearest level 2, linear three quarters of the way from level 1 to level 2.
  const float rho = std::exp2(1.75f);
  CHECK(read(MinFilter::NearestMipmapNearest, rho) == linear(120));
  CHECK(read(MinFilter::LinearMipmapNearest, rho) == linear(120));
  CHECK(read(MinFilter::NearestMipmapLinear, rho) == doctest::Approx(linear(160) + 0.75f * (linear(120) - linear(160))).epsilon(1e-4));
  // rho = 2^1.25: nearest level 1.
  CHECK(read(MinFilter::NearestMipmapNearest, std::exp2(1.25f)) == linear(160));
  // Beyond the last level: the last level.
  CHECK(read(MinFilter::LinearMipmapLinear, 1e6f) == linear(40));
  CHECK(read(MinFilter::NearestMipmapNearest, std::numeric_limits<float>::infinity()) == linear(40));
  // The footprint is the longer of the two screen axes, in texels of each texture axis.
  CHECK(footprintSquared({0.0f, 0.0f, 0.0f, 4.0f / 16.0f}, 16, 16) == 16.0f);
  CHECK(footprintSquared({3.0f / 16.0f, 4.0f / 16.0f, 0.0f, 0.0f}, 16, 16) == 25.0f);
  CHECK(footprintSquared({1.0f / 16.0f, 0.0f, 0.0f, 0.0f}, 64, 16) == 16.0f);
  // NaN derivatives magnify (level 0), as in GLSL, where the comparison is false too.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  CHECK(sampleTexture(t, withMin(MinFilter::LinearMipmapLinear), st, {nan, 0.0f, 0.0f, 0.0f}).r == linear(200));
}

TEST_CASE("within a level: NEAREST reads the texel under the point, LINEAR mixes the four around it") {
  Image image(2, 1);
  image.at(0, 0) = {0, 0, 0, 255}, image.at(1, 0) = {255, 255, 255, 255};
  // s = 0.5 is the boundary between the two texels: NEAREST takes the right one, LINEAR half of each.
  CHECK(sampleLevel(image, TexelEncoding::Srgb, false, Wrap::ClampToEdge, Wrap::ClampToEdge, {0.5f, 0.5f}).r == 1.0f);
  CHECK(sampleLevel(image, TexelEncoding::Srgb, false, Wrap::ClampToEdge, Wrap::ClampToEdge, {0.49f, 0.5f}).r == 0.0f);
  CHECK(sampleLevel(image, TexelEncoding::Srgb, true, Wrap::ClampToEdge, Wrap::ClampToEdge, {0.5f, 0.5f}).r == 0.5f);
  // Beyond the right edge: CLAMP keeps white, REPEAT wraps to black, MIRRORED reflects back to white.
  CHECK(sampleLevel(image, TexelEncoding::Srgb, true, Wrap::ClampToEdge, Wrap::ClampToEdge, {1.0f, 0.5f}).r == 1.0f);
  CHECK(sampleLevel(image, TexelEncoding::Srgb, true, Wrap::Repeat, Wrap::ClampToEdge, {1.0f, 0.5f}).r == 0.5f);
  CHECK(sampleLevel(image, TexelEncoding::Srgb, true, Wrap::MirroredRepeat, Wrap::ClampToEdge, {1.0f, 0.5f}).r == 1.0f);
  CHECK(sampleLevel(image, TexelEncoding::Srgb, false, Wrap::Repeat, Wrap::Repeat, {1.2f, 0.5f}).r == 0.0f);
  CHECK(sampleLevel(image, TexelEncoding::Srgb, false, Wrap::MirroredRepeat, Wrap::Repeat, {1.2f, 0.5f}).r == 1.0f);
}

TEST_CASE("KHR_texture_transform: the coordinates by T*R*S as Khronos' TextureTransformTest shows it, the derivatives by its linear part") {
  Material m;
  m.baseColorTransform.offset = {0.25f, 0.5f};
  m.baseColorTransform.rotation = 1.5707963267948966f;  // pi/2: s' = t * k_y + o_x, t' = -s * k_x + o_y
  m.baseColorTransform.scale = {2.0f, 4.0f};
  const CourseMaterial course = courseMaterial(m, MaterialOverrides{});
  const TransformedTexcoords t = transformTexcoords(course, {0.1f, 0.2f}, {1.0f, 0.0f, 0.0f, 1.0f});
  CHECK(t.st.x == doctest::Approx(0.2f * 4.0f + 0.25f));
  CHECK(t.st.y == doctest::Approx(-0.1f * 2.0f + 0.5f));
  CHECK(t.derivatives.x == doctest::Approx(0.0f).epsilon(1e-6));  // ds'/dx = a*ds/dx + b*dt/dx, no offset
  CHECK(t.derivatives.y == doctest::Approx(-2.0f));
  CHECK(t.derivatives.z == doctest::Approx(4.0f));
  CHECK(t.derivatives.w == doctest::Approx(0.0f).epsilon(1e-6));
  // No transform: the identity, and every finite coordinate unchanged to the bit.
  const CourseMaterial plain = courseMaterial(Material{}, MaterialOverrides{});
  const TransformedTexcoords same = transformTexcoords(plain, {0.3f, -7.25f}, {0.5f, 0.25f, -1.0f, 2.0f});
  CHECK(same.st == glm::vec2(0.3f, -7.25f));
  CHECK(same.derivatives == glm::vec4(0.5f, 0.25f, -1.0f, 2.0f));
}
