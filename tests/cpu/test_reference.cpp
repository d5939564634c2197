// The readable reference (renderer/cpu/reference: one triangle at a time,
// every fragment shaded) against the fast renderer (tiles, threads,
// visibility first, four-lane Phong): the same image and the same triangle at
// every pixel, in every shading mode, with and without shadows and culling,
// textured, clipped by the near plane, at a size no tile divides.
#include <memory>
#include <string>

#include <doctest/doctest.h>

#include "cpu/cpu_renderer.h"
#include "cpu/reference/reference_renderer.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/frame_spine.h"
#include "scene/default_scene.h"
#include "scene/load_scene.h"

using namespace facet;

namespace {

RenderSettings settings(ShadingMode mode, bool shadows, bool cull) {
  RenderSettings s;
  s.width = 173;
  s.height = 131;
  s.shading = mode;
  s.shadows.enabled = shadows;
  s.shadows.mapSize = 256;
  s.cullBackFaces = cull;
  return s;
}

// Pixels where the two images differ, and where the two id buffers differ.
void compare(const Scene& scene, const RenderSettings& s, const std::string& what) {
  CAPTURE(what);
  const FrameInputs frame = buildFrameInputs(scene, s);
  const auto fast = makeCpuRenderer(3);
  const auto reference = makeReferenceRenderer();
  const Image a = fast->render(scene, frame).image, b = reference->render(scene, frame).image;
  long pixels = 0, drawn = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) pixels += a.at(x, y) == b.at(x, y) ? 0 : 1;
  const auto ids = *fast->render(scene, frame, {FrameOutput::TriangleIds}).triangleIds;
  const auto referenceIds = *reference->render(scene, frame, {FrameOutput::TriangleIds}).triangleIds;
  long triangles = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    triangles += ids[i] != referenceIds[i];
    drawn += ids[i] != 0;
  }
  CHECK(pixels == 0);
  CHECK(triangles == 0);
  CHECK(drawn > 1000);  // the comparison means something
}

}  // namespace

TEST_CASE("the fast CPU renderer equals the one-triangle reference on the default scene, every mode, shadows, culling") {
  const Scene scene = makeDefaultScene();
  for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong})
    for (bool shadows : {false, true})
      for (bool cull : {true, false})
        compare(scene, settings(mode, shadows, cull), std::string(kShadingModeNames[static_cast<std::size_t>(mode)]) + (shadows ? " shadows" : "") +
                                                         (cull ? " culled" : " two-sided"));
}

TEST_CASE("the fast CPU renderer equals the one-triangle reference: textured, clipped by the near plane, spot and directional lights") {
  const Scene box = loadScene(std::string(FACET_ASSIMP_MODELS) + "/BoxTextured-glTF/BoxTextured.gltf");
  for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) compare(box, settings(mode, true, true), "textured box");

  const Scene scene = makeDefaultScene();
  RenderSettings near = settings(ShadingMode::Phong, true, false);
  near.camera.source = Source::Manual;  // low, with the ground crossing the near plane
  near.camera.eye = {0.5f, 0.25f, 2.2f};
  near.camera.reference = {0.0f, 0.2f, 0.0f};
  near.camera.near = 0.6f;
  compare(scene, near, "near plane");

  RenderSettings lights = settings(ShadingMode::Gouraud, true, true);
  lights.lightSource = Source::Manual;
  Light spot, sun;
  spot.kind = LightKind::Spot;
  spot.position = {2.5f, 6.0f, 3.0f};
  spot.direction = {-0.35f, -1.0f, -0.45f};
  spot.spotCutoffDeg = 35.0f;
  sun.kind = LightKind::Directional;
  sun.direction = {0.5f, -1.0f, -0.3f};
  lights.lights = {spot, sun};
  compare(scene, lights, "spot and directional");
}

TEST_CASE("the fast CPU renderer equals the one-triangle reference: pbr, normal, emissive, bump and procedural textures, fog") {
  const std::string scenes = std::string(FACET_ASSETS) + "/scenes/";
  for (const char* name : {"normal_map.gltf", "pbr_maps.gltf", "emissive.gltf", "texcoord_sets.gltf"}) {
    const Scene scene = loadScene(scenes + name);
    for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong, ShadingMode::Pbr})
      compare(scene, settings(mode, true, true), std::string(name) + " " + std::string(kShadingModeNames[static_cast<std::size_t>(mode)]));
  }
  RenderSettings bumped = settings(ShadingMode::Phong, true, true);
  bumped.material.bumpMap = std::string(FACET_ASSETS) + "/displacement/height.png";
  const FrameScene bump = FrameSpine(std::make_shared<const Scene>(loadScene(std::string(FACET_ASSETS) + "/bump.gltf"))).scene(bumped);
  compare(*bump.scene, bumped, "bump.gltf");
  const Scene scene = makeDefaultScene();
  RenderSettings procedural = settings(ShadingMode::Phong, true, true);
  procedural.material.procedural = Procedural::Checker;
  procedural.fog.mode = FogMode::Exponential;
  procedural.fog.density = 0.1f;
  compare(scene, procedural, "procedural checker, exponential fog");
}
