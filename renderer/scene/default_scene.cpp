#include "scene/default_scene.h"

#include <cmath>
#include <numbers>

#include "math/elementary.h"
#include "math/transforms.h"
#include "scene/primitives.h"

namespace facet {

Scene makeDefaultScene() {
  constexpr float kDeg = std::numbers::pi_v<float> / 180.0f;
  Scene scene;
  scene.source = "default scene";

  const int ground = scene.addMaterial("ground", {0.45f, 0.45f, 0.42f}, 0.0f, 0.9f);
  const int redPlastic = scene.addMaterial("red plastic", {0.80f, 0.08f, 0.06f}, 0.0f, 0.3f);
  const int bluePaint = scene.addMaterial("blue paint", {0.10f, 0.22f, 0.75f}, 0.0f, 0.6f);
  const int greenRubber = scene.addMaterial("green rubber", {0.12f, 0.55f, 0.18f}, 0.0f, 0.85f);
  const int gold = scene.addMaterial("gold", {1.00f, 0.71f, 0.29f}, 1.0f, 0.35f);

  // Model matrices are built as T·R·S, the order glTF uses.
  scene.addObject(makePlane(32), ground, scaling({5.0f, 1.0f, 5.0f}));
  scene.addObject(makeSphere(32), redPlastic, translation({-1.6f, 0.8f, 0.4f}) * scaling(glm::vec3(0.8f)));
  scene.addObject(makeCube(), bluePaint, translation({1.4f, 0.6f, -0.6f}) * rotationY(30.0f * kDeg) * scaling(glm::vec3(0.6f)));
  scene.addObject(makeCylinder(48), greenRubber, translation({-0.3f, 0.75f, -1.7f}) * scaling({0.45f, 0.75f, 0.45f}));
  scene.addObject(makeTorus(0.7f, 0.3f), gold, translation({0.6f, 0.24f, 1.5f}) * scaling(glm::vec3(0.8f)));

  Light light;
  light.kind = LightKind::Point;
  light.position = {-3.5f, 7.0f, 4.0f};
  light.color = {1.0f, 0.97f, 0.92f};
  light.intensity = 1.0f;
  light.attenuation = {1.0f, 0.0f, 0.002f};
  light.castsShadow = true;
  scene.lights.push_back(light);

  SceneCamera camera;
  camera.name = "default camera";
  camera.eye = {3.9f, 3.0f, 5.4f};
  camera.reference = {0.0f, 0.45f, 0.0f};
  camera.up = {0.0f, 1.0f, 0.0f};
  // A horizontal half-angle θ of 30° at the default 4:3: tan(yfov/2) = tan θ / A_R.
  camera.yfov = 2.0f * elementary::atan(elementary::tan(30.0f * kDeg) * 3.0f / 4.0f);
  camera.near = 0.5f;
  camera.far = 30.0f;
  scene.cameras.push_back(camera);
  return scene;
}

}  // namespace facet
