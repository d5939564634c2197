#include "cpu_test_scenes.h"

#include <algorithm>
#include <cmath>

#include "cpu/cpu_renderer.h"
#include "math/transforms.h"
#include "pipeline/frame_inputs.h"
#include "scene/primitives.h"

namespace facet::test {

Scene groundScene(int subdivisions, glm::vec3 baseColor) {
  Scene scene;
  Mesh plane = makePlane(subdivisions);
  plane.material = 0;
  scene.meshes.push_back(plane);
  scene.instances.push_back({0, scaling({2.0f, 1.0f, 2.0f})});
  Material m;
  m.baseColor = glm::vec4(baseColor, 1.0f);
  m.metallic = 0.0f;
  scene.materials.push_back(m);
  return scene;
}

Scene occluderScene() {
  Scene scene = groundScene(8, {0.8f, 0.8f, 0.8f});
  Mesh cube = makeCube();
  cube.material = 0;
  scene.meshes.push_back(cube);
  scene.instances.push_back({1, translation({0, 0.8f, 0}) * scaling(glm::vec3(0.3f))});
  return scene;
}

RenderSettings topDownSettings(int size) {
  RenderSettings s;
  s.width = s.height = size;
  s.camera.source = Source::Manual;
  s.camera.eye = {0, 10, 0};
  s.camera.reference = {0, 0, 0};
  s.camera.up = {0, 0, -1};
  s.camera.projection = ProjectionKind::Parallel;
  s.camera.parallelWidth = 4.0f;
  s.camera.near = 1.0f;
  s.camera.far = 20.0f;
  s.lightSource = Source::Manual;
  s.shadows.enabled = false;
  s.background = {0, 0, 0};
  return s;
}

RenderSettings shadowedTopDownSettings(int size, Light light) {
  RenderSettings s = topDownSettings(size);
  light.castsShadow = true;
  s.lights = {light};
  s.shadows.enabled = true;
  s.shadows.mapSize = 512;
  s.shadows.pcfRadius = 0;
  return s;
}

glm::vec3 worldAtPixel(int px, int py, int size) {
  const float step = 4.0f / static_cast<float>(size);
  return {(static_cast<float>(px) + 0.5f) * step - 2.0f, 0.0f, 2.0f - (static_cast<float>(py) + 0.5f) * step};
}

Image renderCpu(const Scene& scene, const RenderSettings& settings) {
  return makeCpuRenderer(2)->render(scene, buildFrameInputs(scene, settings)).image;
}

Rgba8 expectedPixel(glm::vec3 linear) {
  const auto channel = [](float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(static_cast<double>(c), 1.0 / 2.4) - 0.055;
    return static_cast<std::uint8_t>(std::lround(encoded * 255.0));
  };
  return {channel(linear.r), channel(linear.g), channel(linear.b), 255};
}

}  // namespace facet::test
