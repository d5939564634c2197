#include "bench_scenes.h"

#include <cmath>
#include <numbers>

#include "common/error.h"
#include "math/transforms.h"
#include "scene/default_scene.h"
#include "scene/primitives.h"

namespace facet {
namespace {

RenderSettings manualSettings(int width, int height) {
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.camera.source = Source::Manual;
  s.lightSource = Source::Manual;
  s.shading = ShadingMode::Phong;
  s.shadows.enabled = false;
  s.ray.spheres = false;  // every column draws the same triangles
  return s;
}

// Ten screen-filling quads drawn back to front: every pixel shaded ~10 times.
// Blended (material.opacity 0.5), each of those fragments is also blended:
// transparency's per-fragment path, with no visibility-first shortcut.
BenchScene fillScene(const std::string& name, bool blended, int width, int height) {
  BenchScene b{name, {}, manualSettings(width, height)};
  if (blended) b.settings.material.opacity = 0.5f;
  b.scene.source = b.name;
  for (int i = 0; i < 10; ++i) {
    const float z = -9.0f + static_cast<float>(i);  // farthest first
    const float t = static_cast<float>(i) / 9.0f;
    // makePlane lies in y = 0 facing +y; Rx(90°) turns it to face +z, the camera.
    b.scene.addObject(makePlane(1), b.scene.addMaterial("layer " + std::to_string(i), {0.2f + 0.6f * t, 0.5f, 0.8f - 0.6f * t}, 0.0f, 0.5f),
              translation({0.0f, 0.0f, z}) * rotationX(0.5f * std::numbers::pi_v<float>) * scaling({40.0f, 1.0f, 40.0f}));
  }
  b.settings.camera.eye = {0.0f, 0.0f, 2.0f};
  b.settings.camera.reference = {0.0f, 0.0f, 0.0f};
  b.settings.camera.near = 0.5f;
  b.settings.camera.far = 20.0f;
  Light light;
  light.position = {1.0f, 1.5f, 3.0f};
  b.settings.lights = {light};
  return b;
}

// The default scene with its own camera and light written as manual settings;
// with `samples` > 1 anti-aliased (four passes of the camera, one of each shadow map).
BenchScene defaultScene(const std::string& name, int samples, int width, int height) {
  BenchScene b{name, makeDefaultScene(), manualSettings(width, height)};
  b.settings.antialiasing.samples = samples;
  const SceneCamera& camera = b.scene.cameras.front();
  b.settings.camera.eye = camera.eye;
  b.settings.camera.reference = camera.reference;
  b.settings.camera.up = camera.up;
  b.settings.camera.near = camera.near;
  b.settings.camera.far = camera.far.value_or(30.0f);
  b.settings.lights = b.scene.lights;
  b.settings.shadows.enabled = true;  // the default settings: a point light, six 2048² maps, PCF r = 1
  return b;
}

// The default scene's ground with 100k particles alive (40,000 born a second, living 2.5 s, at 3 s).
BenchScene particleScene(const std::string& name, int width, int height) {
  BenchScene b = defaultScene(name, 1, width, height);
  Emitter e;
  e.position = {0.0f, 0.02f, 0.0f};
  e.rate = 40000.0f;
  e.lifetime = 2.5f;
  e.spread = 20.0f;
  e.speed = 4.5f;
  e.startSize = 0.03f;
  e.endSize = 0.06f;
  b.settings.particles = {e};
  b.settings.time = 3.0f;
  return b;
}

// The Marschner-Lobb signal at 256³ drawn by `mode`: the iso-surface at 0.5,
// or its values near 0.5 (a thin shell: splatting's sprites fit the frame budget).
BenchScene volumeScene(const std::string& name, VolumeMode mode, int width, int height) {
  BenchScene b{name, {}, manualSettings(width, height)};
  b.scene.source = name;
  b.settings.volume.file = "builtin:marschner-lobb";
  b.settings.volume.resolution = 256;
  b.settings.volume.mode = mode;
  b.settings.volume.center = {0.0f, 0.0f, 0.0f};
  b.settings.volume.rotation = {-65.0f, 30.0f, 0.0f};
  b.settings.volume.transfer = mode == VolumeMode::Splat ? "0.47 1 0.8 0.5 0, 0.5 1 0.8 0.5 0.6, 0.53 1 0.8 0.5 0"
                                                         : "0.42 0.1 0.3 0.9 0, 0.5 0.95 0.7 0.25 0.5, 0.75 0.85 0.25 0.1 0.25, 1 1 0.95 0.9 0.5";
  b.settings.volume.isoValue = 0.5f;
  b.settings.camera.eye = {0.0f, 1.6f, 3.0f};
  b.settings.camera.reference = {0.0f, -0.05f, 0.0f};
  Light light;
  light.position = {-2.0f, 4.0f, 2.5f};
  b.settings.lights = {light};
  return b;
}

}  // namespace

BenchScene sphereScene(const std::string& name, int level, int spotLights, int width, int height, int mapSize) {
  BenchScene b{name, {}, manualSettings(width, height)};
  b.scene.source = name;
  b.scene.addObject(makeSphere(level), b.scene.addMaterial("sphere", {0.8f, 0.1f, 0.08f}, 0.0f, 0.3f), glm::mat4(1.0f));
  b.scene.addObject(makePlane(1), b.scene.addMaterial("ground", {0.45f, 0.45f, 0.42f}, 0.0f, 0.9f),
            translation({0.0f, -1.0f, 0.0f}) * scaling({4.0f, 1.0f, 4.0f}));
  b.settings.camera.eye = {0.0f, 0.6f, 3.2f};
  b.settings.camera.reference = {0.0f, -0.1f, 0.0f};
  b.settings.camera.near = 0.5f;
  b.settings.camera.far = 20.0f;
  Light light;
  light.position = {-2.0f, 4.0f, 2.5f};
  light.attenuation = {1.0f, 0.0f, 0.002f};
  if (spotLights == 0) {
    b.settings.lights = {light};
    return b;
  }
  b.settings.shadows.enabled = true;
  b.settings.shadows.mapSize = mapSize;
  b.settings.shadows.pcfRadius = 1;
  light.kind = LightKind::Spot;
  light.spotCutoffDeg = 40.0f;
  light.intensity = 1.0f / static_cast<float>(spotLights);
  const glm::vec3 first = light.position;
  for (int i = 0; i < spotLights; ++i) {
    // The first light where a single one stands; the others turned about the sphere's vertical axis.
    const float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(spotLights);
    light.position = i == 0 ? first
                            : glm::vec3(first.x * std::cos(angle) + first.z * std::sin(angle), first.y,
                                        -first.x * std::sin(angle) + first.z * std::cos(angle));
    light.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 0.0f) - light.position);
    b.settings.lights.push_back(light);
  }
  return b;
}

std::vector<std::string> allSceneNames() {
  return {"sphere-100k", "sphere-1m",     "sphere-100k-shadow", "sphere-1m-shadow", "fill-10x",     "fill-10x-blended", "default",
          "default-aa4", "particles-100k", "volume-raycast-256", "volume-splat-256", "volume-isosurface-256"};
}

BenchScene makeBenchScene(const std::string& name, int width, int height) {
  if (name == "sphere-100k") return sphereScene(name, kSphere100k, 0, width, height);
  if (name == "sphere-1m") return sphereScene(name, kSphere1M, 0, width, height);
  if (name == "sphere-100k-shadow") return sphereScene(name, kSphere100k, 1, width, height);
  if (name == "sphere-1m-shadow") return sphereScene(name, kSphere1M, 1, width, height);
  if (name == "fill-10x") return fillScene(name, false, width, height);
  if (name == "fill-10x-blended") return fillScene(name, true, width, height);
  if (name == "default") return defaultScene(name, 1, width, height);
  if (name == "default-aa4") return defaultScene(name, 4, width, height);
  if (name == "particles-100k") return particleScene(name, width, height);
  if (name == "volume-raycast-256") return volumeScene(name, VolumeMode::Raycast, width, height);
  if (name == "volume-splat-256") return volumeScene(name, VolumeMode::Splat, width, height);
  if (name == "volume-isosurface-256") return volumeScene(name, VolumeMode::Isosurface, width, height);
  throw Error("bench: unknown scene '" + name + "'");
}

}  // namespace facet
