// The checks of a scene and a frame that both backends rely on
// (pipeline/frame_checks.h), and the light limit, written once: every bad
// input is one facet::Error naming the mesh, instance or key, from the
// shared code, and the CPU backend refuses it before it could read past an
// array (it used to: ASan heap-buffer-overflows in the vertex stage).
#include <string>

#include <doctest/doctest.h>

#include "common/error.h"
#include "cpu/cpu_renderer.h"
#include "pipeline/frame_checks.h"
#include "pipeline/frame_inputs.h"
#include "scene/default_scene.h"
#include "scene/memory_budget.h"
#include "scene/primitives.h"

using namespace facet;

namespace {

Scene cubeScene() {
  Scene scene;
  scene.addObject(makeCube(), scene.addMaterial("grey", glm::vec3(0.5f), 0.0f, 0.5f), glm::mat4(1.0f));
  scene.meshes[0].name = "cube";
  return scene;
}

RenderSettings small() {
  RenderSettings s;
  s.width = 32;
  s.height = 24;
  s.shadows.mapSize = 64;
  return s;
}

}  // namespace

TEST_CASE("a scene's bad mesh data is refused by name, by the shared check that the CPU backend runs first") {
  const Scene good = cubeScene();
  const FrameInputs frame = buildFrameInputs(good, small());
  {
    Scene s = good;
    s.meshes[0].normals.pop_back();
    CHECK_THROWS_WITH_AS(checkScene(s), "mesh 0 'cube': 23 normals for 24 positions", Error);
    CHECK_THROWS_WITH_AS(makeCpuRenderer(1)->render(s, frame), "mesh 0 'cube': 23 normals for 24 positions", Error);
  }
  {
    Scene s = good;
    s.meshes[0].indices[5] = 24;
    CHECK_THROWS_WITH_AS(checkScene(s), "mesh 0 'cube': index 24 (at 5) is not below its 24 positions", Error);
    CHECK_THROWS_WITH_AS(makeCpuRenderer(1)->render(s, frame), "mesh 0 'cube': index 24 (at 5) is not below its 24 positions", Error);
  }
  {
    Scene s = good;
    s.meshes[0].texcoords.assign(3, glm::vec2(0.0f));
    CHECK_THROWS_WITH_AS(makeCpuRenderer(1)->render(s, frame), "mesh 0 'cube': 3 TEXCOORD_0 texture coordinates for 24 positions", Error);
  }
  {
    Scene s = good;
    s.instances[0].mesh = 7;
    CHECK_THROWS_WITH_AS(buildFrameInputs(s, small()), "instance 0: mesh 7 does not exist (the scene has 1)", Error);
  }
  {
    Scene s = good;
    s.materials[0].baseColorTexture = 2;
    CHECK_THROWS_WITH_AS(checkScene(s), "material 0 'grey': base colour texture 2 is missing or empty", Error);
  }
}

TEST_CASE("a frame that does not fit its scene is refused before a backend draws it") {
  const Scene scene = cubeScene();
  FrameInputs frame = buildFrameInputs(scene, small());
  CHECK_NOTHROW(checkFrame(scene, frame));
  CHECK_NOTHROW(checkScene(scene));
  FrameInputs bad = frame;
  bad.instances[0].mesh = 3;
  CHECK_THROWS_WITH_AS(makeCpuRenderer(1)->render(scene, bad), "frame instance 0: mesh 3 is not in the scene", Error);
  bad = frame;
  bad.instances[0].material = 9;
  CHECK_THROWS_WITH_AS(makeCpuRenderer(1)->render(scene, bad, {FrameOutput::TriangleIds}), "frame instance 0: material 9 is not in the frame", Error);
  bad = frame;
  bad.width = 0;
  CHECK_THROWS_WITH_AS(checkFrame(scene, bad), "image size 0x24: each side must be in [1, 16384]", Error);
  bad = frame;
  bad.shadowLayerCount += 1;
  CHECK_THROWS_WITH_AS(checkFrame(scene, bad), "the frame's shadow layer count does not match its lights", Error);
}

TEST_CASE("a renderer checks a scene again once it changed in place, and a copy is a scene of its own") {
  Scene scene = cubeScene();
  const FrameInputs frame = buildFrameInputs(scene, small());
  const auto cpu = makeCpuRenderer(1);
  CHECK_NOTHROW(cpu->render(scene, frame));
  scene.meshes[0].normals.pop_back();
  scene.identity.renew();
  CHECK_THROWS_WITH_AS(cpu->render(scene, frame), "mesh 0 'cube': 23 normals for 24 positions", Error);
  Scene copy = cubeScene();
  CHECK_NOTHROW(cpu->render(copy, frame));
  Scene broken = copy;
  broken.meshes[0].indices[0] = 99;
  CHECK_THROWS_WITH_AS(cpu->render(broken, frame), "mesh 0 'cube': index 99 (at 0) is not below its 24 positions", Error);
}

TEST_CASE("the light limit: a scene's lights beyond it are dropped with a warning, settings beyond it are refused") {
  Scene scene = cubeScene();
  for (int i = 0; i < 10; ++i) {
    Light light;
    light.position = {static_cast<float>(i), 3.0f, 1.0f};
    light.castsShadow = i == 0;
    scene.lights.push_back(light);
  }
  const FrameInputs frame = buildFrameInputs(scene, small());
  REQUIRE(frame.lights.size() == kMaxLights);
  CHECK(frame.lights.back().light.position.x == doctest::Approx(7.0f));  // the first eight, in order
  REQUIRE(frame.warnings.size() == 1);
  CHECK(frame.warnings[0] == "the scene has 10 lights; a frame shades the first 8");

  RenderSettings manual = small();
  manual.lightSource = Source::Manual;
  manual.lights = scene.lights;
  CHECK_THROWS_WITH_AS(buildFrameInputs(scene, manual), "settings key 'lights': 10 lights, a frame shades at most 8", Error);
}

TEST_CASE("frame budget: shadow maps and instance buffers are priced before a backend allocates them") {
  // The case: a scene of many point lights keeps eight. At the default
  // map size their 8 x 6 faces of 2048^2 depth (768 MiB) fit; at 4096 they do not.
  Scene scene = cubeScene();
  scene.source = "lamps.gltf";
  for (int i = 0; i < 8; ++i) {
    Light light;
    light.position = {static_cast<float>(i), 3.0f, 1.0f};
    scene.lights.push_back(light);
  }
  RenderSettings settings = small();
  settings.shadows.mapSize = RenderSettings{}.shadows.mapSize;
  REQUIRE(settings.shadows.mapSize == 2048);
  CHECK_NOTHROW(buildFrameInputs(scene, settings));
  settings.shadows.mapSize = 4096;
  CHECK_THROWS_WITH_AS(buildFrameInputs(scene, settings),
                       "lamps.gltf: the shadow maps of 8 lights (48 faces of 4096x4096 depth texels) need 3 GiB, more than the frame budget of "
                       "1 GiB (settings key 'shadows.mapSize': 2364 or less fits, or shadows.enabled=false)",
                       Error);
  settings.shadows.mapSize = 2364;
  const FrameInputs fits = buildFrameInputs(scene, settings);
  CHECK(shadowMapBytes(fits.shadows.mapSize, fits.shadowLayerCount) <= kFrameMemoryBudget);
  settings.shadows.mapSize = 4096;
  settings.shadows.enabled = false;
  CHECK_NOTHROW(buildFrameInputs(scene, settings));
  // The shared check refuses a frame made by hand too, before the CPU backend sizes its maps.
  FrameInputs bad = fits;
  bad.shadows.mapSize = 2365;
  CHECK_THROWS_WITH_AS(makeCpuRenderer(1)->render(scene, bad), doctest::Contains("more than the frame budget of 1 GiB"), Error);

  // One mesh placed many times: the instances' vertex and triangle buffers.
  Scene many = cubeScene();
  many.source = "many.gltf";
  const std::uint64_t perInstance = instanceFrameBytes(many.meshes[0].positions.size(), many.meshes[0].triangleCount());
  const std::uint64_t fitting = kFrameMemoryBudget / perInstance;
  many.instances.assign(fitting, many.instances[0]);
  settings.shadows.enabled = false;
  CHECK_NOTHROW(buildFrameInputs(many, settings));
  many.instances.push_back(many.instances[0]);
  CHECK_THROWS_WITH_AS(buildFrameInputs(many, settings),
                       doctest::Contains(("many.gltf: the vertex and triangle buffers of " + std::to_string(fitting + 1) + " instances (").c_str()), Error);
}
