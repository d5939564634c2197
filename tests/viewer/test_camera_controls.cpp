// The orbit camera's moves: what each keeps, what each changes.
#include <cmath>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "pipeline/frame_inputs.h"
#include "scene/default_scene.h"
#include "viewer/camera_controls.h"

using namespace facet;
using namespace facet::viewer;

namespace {

CameraSettings frontCamera() {
  CameraSettings c;
  c.source = Source::Manual;
  c.eye = {0.0f, 0.0f, 10.0f};
  c.reference = {0.0f, 0.0f, 0.0f};
  c.up = {0.0f, 1.0f, 0.0f};
  c.halfAngleDeg = 45.0f;
  c.near = 5.0f;
  c.far = 15.0f;
  return c;
}

void checkNear(glm::vec3 a, glm::vec3 b) {
  CHECK(a.x == doctest::Approx(b.x).epsilon(1e-4));
  CHECK(a.y == doctest::Approx(b.y).epsilon(1e-4));
  CHECK(a.z == doctest::Approx(b.z).epsilon(1e-4));
}

float degreesFromUp(const CameraSettings& c) {
  return glm::degrees(std::acos(glm::dot(glm::normalize(c.eye - c.reference), glm::normalize(c.up))));
}

}  // namespace

TEST_CASE("a horizontal drag of half the window height turns the eye 90 degrees about v_up") {
  CameraSettings c = frontCamera();
  orbit(c, {300.0f, 0.0f}, 600.0f);
  checkNear(c.reference, {0.0f, 0.0f, 0.0f});
  CHECK(glm::length(c.eye - c.reference) == doctest::Approx(10.0f));
  // Dragging right carries the scene right: the eye goes round to its left, -x.
  checkNear(c.eye, {-10.0f, 0.0f, 0.0f});
}

TEST_CASE("a vertical drag looks from higher up and stops short of v_up") {
  CameraSettings c = frontCamera();
  orbit(c, {0.0f, 100.0f}, 600.0f);  // 30 degrees
  CHECK(degreesFromUp(c) == doctest::Approx(60.0f));
  CHECK(c.eye.y > 0.0f);
  orbit(c, {0.0f, 10000.0f}, 600.0f);
  CHECK(degreesFromUp(c) == doctest::Approx(1.0f).epsilon(1e-3));  // acos near 0 keeps few bits
  orbit(c, {0.0f, -10000.0f}, 600.0f);
  CHECK(degreesFromUp(c) == doctest::Approx(179.0f).epsilon(1e-3));
  CHECK(glm::length(c.eye - c.reference) == doctest::Approx(10.0f));
}

TEST_CASE("a pan across the whole window moves eye and reference by the width of view at P_ref") {
  CameraSettings c = frontCamera();  // θ = 45°, d = 10: W = 2 d tan θ = 20
  pan(c, {800.0f, 0.0f}, 800.0f);
  checkNear(c.eye, {-20.0f, 0.0f, 10.0f});
  checkNear(c.reference, {-20.0f, 0.0f, 0.0f});
  pan(c, {0.0f, 400.0f}, 800.0f);  // down on screen: the scene follows, the camera goes up
  checkNear(c.reference, {-20.0f, 10.0f, 0.0f});

  c = frontCamera();
  c.projection = ProjectionKind::Parallel;
  c.parallelWidth = 4.0f;
  pan(c, {-400.0f, 0.0f}, 800.0f);
  checkNear(c.reference, {2.0f, 0.0f, 0.0f});
}

TEST_CASE("each wheel step takes 10% off the distance, or off W in parallel, down to a minimum distance") {
  CameraSettings c = frontCamera();
  zoom(c, 1.0f, 0.01f);
  checkNear(c.eye, {0.0f, 0.0f, 9.0f});
  zoom(c, -2.0f, 0.01f);
  CHECK(c.eye.z == doctest::Approx(9.0f / 0.81f));
  zoom(c, 1000.0f, 0.5f);
  CHECK(glm::length(c.eye - c.reference) == doctest::Approx(0.5f));

  c = frontCamera();
  c.projection = ProjectionKind::Parallel;
  c.parallelWidth = 10.0f;
  zoom(c, 1.0f, 0.01f);
  CHECK(c.parallelWidth == doctest::Approx(9.0f));
  checkNear(c.eye, {0.0f, 0.0f, 10.0f});
}

TEST_CASE("switching projection keeps the width of view at P_ref, and back again") {
  const Sphere sphere{{0.0f, 0.0f, 0.0f}, 1.0f};
  CameraSettings c = frontCamera();
  toggleProjection(c, sphere);
  CHECK(c.projection == ProjectionKind::Parallel);
  CHECK(c.parallelWidth == doctest::Approx(20.0f));
  c.parallelWidth = 10.0f;
  toggleProjection(c, sphere);
  CHECK(c.projection == ProjectionKind::Perspective);
  checkNear(c.eye, {0.0f, 0.0f, 5.0f});  // d = W / (2 tan θ)
  CHECK(c.near == doctest::Approx(0.01f));  // 5 - 5, held at F/1000
  CHECK(c.far == doctest::Approx(10.0f));
}

TEST_CASE("N and F move with the eye, so a zoom keeps the scene where it was in the depth range") {
  const Sphere sphere{{0.0f, 0.0f, 0.0f}, 2.0f};
  CameraSettings c = frontCamera();
  c.near = 7.0f;  // cuts 1 into the sphere on purpose
  c.far = 12.0f;
  const CameraSettings before = c;
  zoom(c, 2.0f, 0.01f);  // d: 10 -> 8.1
  moveDepthRange(c, before, sphere);
  CHECK(c.near == doctest::Approx(5.1f));
  CHECK(c.far == doctest::Approx(10.1f));

  const CameraSettings orbited = c;
  orbit(c, {123.0f, 45.0f}, 600.0f);  // about P_ref, the sphere's centre: no change
  moveDepthRange(c, orbited, sphere);
  CHECK(c.near == doctest::Approx(5.1f));
  CHECK(c.far == doctest::Approx(10.1f));
}

TEST_CASE("moves on the default scene's camera give frames buildFrameInputs accepts") {
  const Scene scene = makeDefaultScene();
  RenderSettings settings = materialize(scene, RenderSettings{}, true, false);
  const Sphere sphere = sceneSphere(scene);
  for (int i = 0; i < 20; ++i) {
    const CameraSettings before = settings.camera;
    orbit(settings.camera, {37.0f, i % 2 ? 80.0f : -120.0f}, 600.0f);
    pan(settings.camera, {5.0f, -3.0f}, 800.0f);
    zoom(settings.camera, i % 3 ? 1.0f : -2.0f, 1e-3f * sphere.radius);
    moveDepthRange(settings.camera, before, sphere);
    if (i % 5 == 0) toggleProjection(settings.camera, sphere);
    CHECK_NOTHROW(buildFrameInputs(scene, settings));
    CHECK(settings.camera.near > 0.0f);
    CHECK(settings.camera.near < settings.camera.far);
  }
}
