// buildFrameInputs: the camera and light matrices every backend consumes.
#include <cmath>
#include <initializer_list>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "common/error.h"
#include "cpu/cpu_renderer.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/view_setup.h"
#include "scene/default_scene.h"
#include "scene/primitives.h"

using namespace facet;

namespace {

glm::vec3 project(const glm::mat4& m, glm::vec3 p) {
  const glm::vec4 c = m * glm::vec4(p, 1.0f);
  return glm::vec3(c) / c.w;
}

bool insideUnitBox(glm::vec3 ndc) {
  return std::fabs(ndc.x) <= 1.0f && std::fabs(ndc.y) <= 1.0f && ndc.z >= 0.0f && ndc.z <= 1.0f;
}

Scene sphereScene() {
  Scene scene;
  scene.meshes.push_back(makeSphere(8));
  scene.instances.push_back({0, glm::mat4(1.0f)});
  return scene;
}

}  // namespace

TEST_CASE("the default scene's camera puts the reference point at the image centre") {
  const Scene scene = makeDefaultScene();
  const FrameInputs f = buildFrameInputs(scene, RenderSettings{});
  CHECK(f.camera.halfAngleDeg == doctest::Approx(30.0f));  // the scene camera's yfov at 4:3
  const glm::vec3 centre = project(f.windowFromNdc * f.clipFromWorld, scene.cameras[0].reference);
  CHECK(centre.x == doctest::Approx(400.0f));
  CHECK(centre.y == doctest::Approx(300.0f));
  REQUIRE(f.lights.size() == 1);
  CHECK(f.lights[0].hasShadowMap);
  CHECK(f.lights[0].frustum.faceCount == 6);
  CHECK(f.materials.size() == scene.materials.size() + 1);
}

TEST_CASE("an auto camera frames a scene that has none, and the whole sphere is in view") {
  const Scene scene = sphereScene();
  const FrameInputs f = buildFrameInputs(scene, RenderSettings{});
  for (const glm::vec3 p : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)})
    CHECK(insideUnitBox(project(f.clipFromWorld, p)));
  RenderSettings parallelView;
  parallelView.camera.projection = ProjectionKind::Parallel;
  const FrameInputs g = buildFrameInputs(scene, parallelView);
  CHECK_FALSE(g.perspective);
  for (const glm::vec3 p : {glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1)}) CHECK(insideUnitBox(project(g.clipFromWorld, p)));
}

TEST_CASE("light frusta of every kind hold the scene's bounding sphere") {
  const Scene scene = sphereScene();
  for (LightKind kind : {LightKind::Point, LightKind::Spot, LightKind::Directional}) {
    CAPTURE(static_cast<int>(kind));
    Light light;
    light.kind = kind;
    light.position = {0.5f, 4.0f, 0.3f};
    light.direction = glm::normalize(glm::vec3(-0.5f, -4.0f, -0.3f));
    light.spotCutoffDeg = 30.0f;
    const LightFrustum frustum = lightFrustum(light, sceneSphere(scene));
    for (const glm::vec3 p : {glm::vec3(0.9f, 0, 0), glm::vec3(0, 0.95f, 0), glm::vec3(0, -0.95f, 0), glm::vec3(0, 0, -0.9f)}) {
      const int face = kind == LightKind::Point ? cubeFace(p - light.position) : 0;
      CHECK(insideUnitBox(project(frustum.clipFromWorld[static_cast<std::size_t>(face)], p)));
    }
  }
}

TEST_CASE("cube faces: largest absolute component, ties to x, then y, then z") {
  CHECK(cubeFace({2, 1, 1}) == 0);
  CHECK(cubeFace({-2, 1, 1}) == 1);
  CHECK(cubeFace({0, 3, -1}) == 2);
  CHECK(cubeFace({0, -3, 1}) == 3);
  CHECK(cubeFace({0, 0, 1}) == 4);
  CHECK(cubeFace({0, 0, -1}) == 5);
  CHECK(cubeFace({1, 1, 1}) == 0);    // x wins a three-way tie
  CHECK(cubeFace({0, -1, 1}) == 3);   // y wins over z
  CHECK(cubeFace({-1, 0, -1}) == 1);  // x wins over z
}

TEST_CASE("a camera with no view direction is a named error") {
  RenderSettings s;
  s.camera.source = Source::Manual;
  s.camera.eye = s.camera.reference = {1, 2, 3};
  CHECK_THROWS_WITH_AS(buildFrameInputs(sphereScene(), s), doctest::Contains("settings key 'camera'"), Error);
}

TEST_CASE("a scene as large as kMaxWorldCoordinate is framed and drawn as the same scene at unit size") {
  // The loader drops what lies beyond kMaxWorldCoordinate; up to it the
  // pipeline's float squares (N·F, d²) must stay finite, and the auto
  // camera and light frame it as they frame the scene at unit size (a
  // power of two scales every float exactly: the same bytes). Beyond 1.8e19
  // the bounding radius overflowed and the image came out empty.
  const auto render = [](float scale, bool shadows) {
    Scene scene = sphereScene();
    for (glm::vec3& p : scene.meshes[0].positions) p *= scale;
    RenderSettings s;
    s.width = 48;
    s.height = 32;
    s.shadows.mapSize = 64;
    s.shadows.enabled = shadows;
    const FrameInputs f = buildFrameInputs(scene, s);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) {
        REQUIRE(std::isfinite(f.clipFromWorld[c][r]));
        if (shadows) REQUIRE(std::isfinite(f.lights[0].shadowFromWorld[0][c][r]));
      }
    return makeCpuRenderer(1)->render(scene, f).image;
  };
  const auto covered = [](const Image& image) {
    std::size_t n = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) n += image.at(x, y) == image.at(0, 0) ? 0 : 1;
    return n;
  };
  const float scale = std::exp2(std::floor(std::log2(kMaxWorldCoordinate)));
  CHECK(scale * 2.0f > kMaxWorldCoordinate);
  const Image unit = render(1.0f, false);
  CHECK(covered(unit) > 150);  // the sphere is in the picture
  CHECK(render(scale, false) == unit);
  // With its shadow map too: a view one unit along the light's axis from a
  // light 2^24 away was the light itself, and the maps NaN.
  CHECK(render(scale, true) == render(1.0f, true));
}
