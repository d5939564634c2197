// glTF normal textures (renderer/PIPELINE.md, "Textures"): a flat texel keeps
// the normal, a tilted one turns it toward T or B by its x and y, the scale
// multiplies x and y, and w picks the bitangent's side.
#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "shading/bump_mapping.h"
#include "shading/normal_mapping.h"

using namespace facet;

namespace {

// A 1×1 data texture holding one tangent-space normal n, as bytes round((n + 1)/2·255).
Texture normalTexel(glm::vec3 n) {
  Texture t;
  const auto byte = [](float c) { return static_cast<std::uint8_t>(std::lround((c + 1.0f) * 0.5f * 255.0f)); };
  t.image = Image(1, 1, {byte(n.x), byte(n.y), byte(n.z), 255});
  t.encoding = TexelEncoding::Linear;
  return t;
}

glm::vec3 bent(const Texture& map, float scale, glm::vec4 tangent) {
  CourseMaterial m;
  m.normalScale = scale;
  return glm::normalize(normalMapped(map, m, {0, 0, 1}, tangent, {0.5f, 0.5f}, glm::vec4(0.0f)));
}

}  // namespace

TEST_CASE("normal textures: a flat texel keeps N, a tilted one turns N toward T or B, scaled, on w's side") {
  const glm::vec4 T(1, 0, 0, 1);
  CHECK(glm::length(bent(normalTexel({0, 0, 1}), 1.0f, T) - glm::vec3(0, 0, 1)) < 0.01f);
  const glm::vec3 toT = bent(normalTexel(glm::normalize(glm::vec3(0.5f, 0, 1))), 1.0f, T);
  CHECK(toT.x > 0.4f);
  CHECK(std::fabs(toT.y) < 0.01f);
  const glm::vec3 toB = bent(normalTexel(glm::normalize(glm::vec3(0, 0.5f, 1))), 1.0f, T);
  CHECK(toB.y > 0.4f);  // B = w·(N × T) = +y
  CHECK(bent(normalTexel(glm::normalize(glm::vec3(0, 0.5f, 1))), 1.0f, {1, 0, 0, -1}).y < -0.4f);
  // The scale multiplies x and y: twice the tilt.
  const glm::vec3 doubled = bent(normalTexel(glm::normalize(glm::vec3(0.3f, 0, 1))), 2.0f, T);
  const glm::vec3 once = bent(normalTexel(glm::normalize(glm::vec3(0.3f, 0, 1))), 1.0f, T);
  CHECK(doubled.x / doubled.z == doctest::Approx(2.0f * once.x / once.z).epsilon(0.02));
  // A tangent that is not perpendicular to N is made so: the result does not lean along N's own direction.
  const glm::vec3 leaning = bent(normalTexel({0, 0, 1}), 1.0f, {1, 0, 0.8f, 1});
  CHECK(glm::length(leaning - glm::vec3(0, 0, 1)) < 0.01f);
}

TEST_CASE("bump mapping: a level height map keeps N, a ramp tilts N away from uphill by the course's formula, scaled by k") {
  Texture level, ramp;
  level.image = Image(8, 8, {128, 128, 128, 255});
  ramp.image = Image(8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) ramp.image.at(x, y) = {static_cast<std::uint8_t>(16 * x + 8), static_cast<std::uint8_t>(16 * x + 8), static_cast<std::uint8_t>(16 * x + 8), 255};
  level.encoding = ramp.encoding = TexelEncoding::Linear;
  const glm::vec3 N(0, 0, 1);
  const glm::vec4 T(1, 0, 0, 1);
  CHECK(glm::length(bumped(level, 0.5f, N, T, {0.5f, 0.5f}) - N) < 1e-6f);
  // h rises along s by 16/255 per texel, 8 texels per unit: dh/ds = 128/255; N' = N - k·(dh/ds)·T.
  const glm::vec3 tilted = bumped(ramp, 0.5f, N, T, {0.5f, 0.5f});
  CHECK(tilted.x == doctest::Approx(-0.5 * 128.0 / 255.0).epsilon(1e-4));
  CHECK(std::fabs(tilted.y) < 1e-6f);
  CHECK(tilted.z == 1.0f);
  CHECK(bumped(ramp, 1.0f, N, T, {0.5f, 0.5f}).x == doctest::Approx(2.0 * tilted.x).epsilon(1e-4));
}
