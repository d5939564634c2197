// buildFrameInputs: the camera and light matrices every backend consumes.
#include <cmath>
#include <initializer_list>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "common/error.h"
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
