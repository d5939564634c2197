#include "scene/cornell_box.h"

#include <cmath>
#include <numbers>

#include "math/elementary.h"
#include "math/transforms.h"
#include "scene/primitives.h"

namespace facet {

Scene makeCornellBox() {
  constexpr float kQuarter = std::numbers::pi_v<float> / 2.0f;
  constexpr float kHalfWidth = 1.35f;  // x in [-1.35, 1.35], y in [0, 2], z in [-1, 1]: wide enough for a 4:3 view
  Scene scene;
  scene.source = "builtin:cornell";
  const int white = scene.addMaterial("white wall", {0.73f, 0.73f, 0.73f}, 0.0f, 0.9f);
  const int red = scene.addMaterial("red wall", {0.63f, 0.065f, 0.05f}, 0.0f, 0.9f);
  const int green = scene.addMaterial("green wall", {0.14f, 0.45f, 0.091f}, 0.0f, 0.9f);
  const int mirror = scene.addMaterial("mirror", {0.95f, 0.95f, 0.95f}, 1.0f, 0.0f);
  const int glass = scene.addMaterial("glass", {1.0f, 1.0f, 1.0f}, 0.0f, 0.0f);
  scene.materials[static_cast<std::size_t>(glass)].transmission = 1.0f;
  scene.materials[static_cast<std::size_t>(glass)].ior = 1.5f;
  const int panel = scene.addMaterial("light panel", {1.0f, 1.0f, 1.0f}, 0.0f, 1.0f);
  scene.materials[static_cast<std::size_t>(panel)].emissive = glm::vec3(1.0f);

  // The unit plane y = 0 (normal +y, [-1, 1]² in x and z) turned into each wall, facing the inside.
  const glm::mat4 wide = scaling({kHalfWidth, 1.0f, 1.0f});
  scene.addObject(makePlane(8), white, wide);                                                                  // floor
  scene.addObject(makePlane(8), white, translation({0.0f, 2.0f, 0.0f}) * rotationX(2.0f * kQuarter) * wide);  // ceiling
  scene.addObject(makePlane(8), white, translation({0.0f, 1.0f, -1.0f}) * rotationX(kQuarter) * wide);        // back
  scene.addObject(makePlane(8), red, translation({-kHalfWidth, 1.0f, 0.0f}) * rotationZ(-kQuarter));           // left
  scene.addObject(makePlane(8), green, translation({kHalfWidth, 1.0f, 0.0f}) * rotationZ(kQuarter));           // right
  scene.addObject(makePlane(1), panel, translation({0.0f, 1.995f, 0.0f}) * rotationX(2.0f * kQuarter) * scaling({0.3f, 1.0f, 0.3f}));
  scene.addObject(makeSphere(32), mirror, translation({-0.55f, 0.45f, -0.35f}) * scaling(glm::vec3(0.45f)));
  scene.addObject(makeSphere(32), glass, translation({0.6f, 0.45f, 0.35f}) * scaling(glm::vec3(0.45f)));

  Light light;
  light.kind = LightKind::Point;
  light.position = {0.0f, 1.9f, 0.0f};
  light.color = {1.0f, 0.95f, 0.88f};
  light.intensity = 1.0f;
  light.attenuation = {1.0f, 0.0f, 0.05f};
  light.castsShadow = true;
  light.radius = 0.08f;  // soft shadows with ray.samples above 1; within the 0.095 below the panel
  scene.lights.push_back(light);

  SceneCamera camera;
  camera.name = "cornell camera";
  camera.eye = {0.0f, 1.0f, 3.9f};
  camera.reference = {0.0f, 1.0f, 0.0f};
  camera.yfov = 2.0f * elementary::atan(1.0f / 2.9f);  // the open side, 2 high, 2.9 away, fills the height
  camera.near = 0.5f;
  camera.far = 10.0f;
  scene.cameras.push_back(camera);
  return scene;
}

}  // namespace facet
