// Environment mapping (renderer/PIPELINE.md, "Textures"): the cube strip is
// read as OpenGL's cube-map table says, the reflection is k_r·env(R) in the
// highlights, and the background shows the map in each pixel's direction.
#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "shading/environment.h"
#include "shading/lighting.h"
#include "image/srgb.h"
#include "pipeline/frame_inputs.h"
#include "scene/default_scene.h"
#include "scene/environment_map.h"

using namespace facet;

namespace {

constexpr int kFace = 4;

// A 6·4 × 4 strip whose every texel is distinct: red = face·40 + column·8, green = the row from the top · 60.
EnvironmentMap codedStrip() {
  EnvironmentMap map;
  map.path = "coded";
  map.faces = Image(6 * kFace, kFace);
  for (int face = 0; face < 6; ++face)
    for (int column = 0; column < kFace; ++column)
      for (int row = 0; row < kFace; ++row)
        map.faces.at(face * kFace + column, kFace - 1 - row) = {static_cast<std::uint8_t>(face * 40 + column * 8),
                                                               static_cast<std::uint8_t>(row * 60), 0, 255};
  return map;
}

// The direction OpenGL's table (sc, tc, ma per face) sends to the centre of texel (column, row from the top).
glm::vec3 towards(int face, int column, int row) {
  const float a = 2.0f * (static_cast<float>(column) + 0.5f) / kFace - 1.0f, b = 2.0f * (static_cast<float>(row) + 0.5f) / kFace - 1.0f;
  const glm::vec3 directions[6] = {{1, -b, -a}, {-1, -b, a}, {a, 1, b}, {a, -1, -b}, {a, -b, 1}, {-a, -b, -1}};
  return directions[face];
}

}  // namespace

TEST_CASE("env(D) reads the face of D's largest component at OpenGL's cube-map coordinates, texel by texel") {
  const EnvironmentMap map = codedStrip();
  const float* decoded = srgbTables().decoded.data();
  for (int face = 0; face < 6; ++face)
    for (int column = 0; column < kFace; ++column)
      for (int row = 0; row < kFace; ++row) {
        CAPTURE(face);
        CAPTURE(column);
        CAPTURE(row);
        const glm::vec3 c = environmentAt(map, towards(face, column, row), 0);
        CHECK(c.r == decoded[face * 40 + column * 8]);
        CHECK(c.g == decoded[row * 60]);
      }
  // Ties go to x, then y: (1, 1, 0) reads +x, (0, 1, 1) reads +y.
  CHECK(environmentAt(map, {1, 1, 0}, 0).r >= decoded[0]);
  CHECK(environmentAt(map, {1, 1, 0}, 0).r < decoded[40]);
  CHECK(environmentAt(map, {0, 1, 1}, 0).r >= decoded[80]);
  CHECK(environmentAt(map, {0, 1, 1}, 0).r < decoded[120]);
}

TEST_CASE("the reflection adds k_r env(R) to the highlights, and the background is env(F) at the image centre") {
  Scene scene = makeDefaultScene();
  scene.environment = codedStrip();
  RenderSettings s;
  s.width = 65, s.height = 49;  // odd: pixel (32, 24) is the centre
  s.environment.map = "coded";
  s.environment.reflectivity = 0.5f;
  s.lightSource = Source::Manual;  // no lights: the illumination is ambient plus the reflection
  const FrameInputs frame = buildFrameInputs(scene, s);
  REQUIRE(frame.environment.map != nullptr);
  CHECK(backgroundAt(frame, 32, 24) == environmentAt(scene.environment, frame.environment.forward, 0));
  CHECK(glm::length(frame.environment.forward) == doctest::Approx(1.0f));
  const ShadowMaps maps;
  LaneMaterial<float> dielectric{};
  const glm::vec3 N{0, 1, 0}, V = glm::normalize(glm::vec3(1, 1, 0));  // R = (-1, 1, 0)/√2 ... reflected about N
  const glm::vec3 R = (2.0f * glm::dot(N, V)) * N - V;
  const Illumination I = illuminate(frame, maps, dielectric, glm::vec3(0.0f), N, V);
  const glm::vec3 expected = 0.5f * environmentAt(scene.environment, R, 0);
  CHECK(I.specular.r == doctest::Approx(expected.r));
  CHECK(I.specular.g == doctest::Approx(expected.g));
  LaneMaterial<float> metal{};
  metal.metallic = 1.0f;
  const Illumination M = illuminate(frame, maps, metal, glm::vec3(0.0f), N, V);
  CHECK(M.specular.r == 0.0f);                                  // a metal's reflection is tinted by O_d: it moves to the diffuse part
  CHECK(M.diffuse.r == doctest::Approx(expected.r));
  // Without a map the frame has no reflection and the background is the colour.
  Scene plain = makeDefaultScene();
  s.environment.map.clear();
  const FrameInputs without = buildFrameInputs(plain, s);
  CHECK(backgroundAt(without, 32, 24) == without.background);
  CHECK(illuminate(without, maps, dielectric, glm::vec3(0.0f), N, V).specular == glm::vec3(0.0f));
}
