// What the stages of a frame mean (renderer/PIPELINE.md, "Rasterization",
// "Stages"), held on both rasterizers: the agreement suite's stage cases
// hold the two equal, these hold each to what the stage is. Depth grows
// away from the eye; a point light's shadow-map face holds the objects'
// silhouettes, nearer the light than the ground; a sphere's centre pixel
// faces the eye in the normals; light-0 of a one-light frame and the frame
// without lights add up to the frame. And the stage list itself: its names,
// its refusals, its pictures.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "common/error.h"
#include "cpu/cpu_renderer.h"
#include "cpu/reference/reference_renderer.h"
#include "gl/gl_renderer.h"
#include "image/srgb.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/shadow_pass_key.h"
#include "pipeline/stage_frames.h"
#include "pipeline/view_setup.h"
#include "ray/ray_renderer.h"
#include "render/stage.h"
#include "scene/default_scene.h"
#include "scene/load_scene.h"

using namespace facet;

namespace {

Renderer& glRenderer() {
  static std::unique_ptr<Renderer> renderer = makeGlRenderer(GlContextKind::OsMesa);  // one context for the whole run
  return *renderer;
}

Renderer& cpuRenderer() {
  static std::unique_ptr<Renderer> renderer = makeCpuRenderer(2);
  return *renderer;
}

// Both rasterizers, by name: each test holds each to the stage's meaning.
const std::array<std::pair<const char*, Renderer& (*)()>, 2> kBackends = {{{"gl", glRenderer}, {"cpu", cpuRenderer}}};

RenderSettings sized(int width, int height) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  return settings;
}

std::size_t pixelIndex(const FrameInputs& frame, int x, int y) {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(x);
}

// The default scene's frame with only the ground (its first instance) left.
FrameInputs groundOnly(FrameInputs frame) {
  frame.instances.resize(1);
  return frame;
}

}  // namespace

TEST_CASE("depth: a surface in front of the ground has a smaller window z than the ground behind it, along the same ray") {
  const Scene scene = makeDefaultScene();
  const FrameInputs frame = buildFrameInputs(scene, sized(160, 120));
  const std::size_t groundTriangles = scene.meshes[static_cast<std::size_t>(frame.instances[0].mesh)].indices.size() / 3;
  for (const auto& [name, renderer] : kBackends) {
    const std::string backend = name;
    CAPTURE(backend);
    const std::vector<float> full = *renderer().render(scene, frame, {FrameOutput::Depth}).depth;
    const std::vector<float> ground = *renderer().render(scene, groundOnly(frame), {FrameOutput::Depth}).depth;
    const std::vector<std::uint32_t> kept = *renderer().render(scene, frame, {FrameOutput::TriangleIds}).triangleIds;
    REQUIRE(full.size() == kept.size());
    long inFront = 0, misordered = 0, drawnMismatch = 0;
    for (std::size_t i = 0; i < full.size(); ++i) {
      drawnMismatch += (full[i] < 1.0f) != (kept[i] != 0);  // triangles only: z < 1 exactly where one is kept
      misordered += !(full[i] <= ground[i]);                 // more surfaces never push the z-buffer back
      if (kept[i] > groundTriangles && ground[i] < 1.0f) {   // an object, with the ground behind it
        inFront += 1;
        misordered += !(full[i] < ground[i]);
      }
    }
    CHECK(drawnMismatch == 0);
    CHECK(misordered == 0);
    CHECK(inFront > 1000);
  }
}

TEST_CASE("depth: window z grows with the eye depth of what a pixel shows") {
  // Down a corridor of the ground: farther rows of a ground seen from above it show farther points.
  const Scene scene = makeDefaultScene();
  FrameInputs frame = groundOnly(buildFrameInputs(scene, sized(64, 96)));
  for (const auto& [name, renderer] : kBackends) {
    const std::string backend = name;
    CAPTURE(backend);
    const std::vector<float> depth = *renderer().render(scene, frame, {FrameOutput::Depth}).depth;
    // The ground's pixels in the middle column: up the image is farther from the eye (the camera looks down on it).
    float last = 0.0f;
    int rows = 0;
    for (int y = 0; y < frame.height; ++y) {
      const float z = depth[pixelIndex(frame, frame.width / 2, y)];
      if (!(z < 1.0f)) continue;
      CHECK(z > last);
      last = z;
      ++rows;
    }
    CHECK(rows > 20);
  }
}

TEST_CASE("shadow-map: the default scene's point light holds the objects' silhouettes, nearer the light than the ground") {
  const Scene scene = makeDefaultScene();
  RenderSettings settings = sized(64, 48);
  settings.shadows.mapSize = 256;
  const FrameInputs frame = buildFrameInputs(scene, settings);
  FrameInputs groundCasts = frame;  // the same maps with the ground alone casting
  for (std::size_t m = 0; m < groundCasts.materials.size(); ++m)
    groundCasts.materials[m].castsShadow = static_cast<int>(m) == frame.instances[0].material;
  FrameInputs noneCasts = frame;
  for (CourseMaterial& material : noneCasts.materials) material.castsShadow = false;

  // The sphere's centre, seen from the light: its -y face (the light is above it), the sphere's top in front of the centre.
  const FrameLight& light = frame.lights[0];
  REQUIRE(light.frustum.faceCount == 6);
  const glm::vec3 sphereCentre(-1.6f, 0.8f, 0.4f);
  const int face = 3;  // -y: the largest component of centre - light is y, negative
  const glm::vec4 s = light.shadowFromWorld[face] * glm::vec4(sphereCentre, 1.0f);
  const float u = s.x / s.w, v = s.y / s.w, zCentre = s.z / s.w;
  REQUIRE(u > 0.0f);
  REQUIRE(u < 1.0f);
  REQUIRE(v > 0.0f);
  REQUIRE(v < 1.0f);
  const std::size_t S = 256, perLayer = S * S;
  const std::size_t centreTexel = static_cast<std::size_t>(face) * perLayer + static_cast<std::size_t>(v * 256.0f) * S + static_cast<std::size_t>(u * 256.0f);

  for (const auto& [name, renderer] : kBackends) {
    const std::string backend = name;
    CAPTURE(backend);
    const ShadowMapTexels maps = *renderer().render(scene, frame, {FrameOutput::ShadowMaps}).shadowMaps;
    REQUIRE(maps.size == 256);
    REQUIRE(maps.layers == 6);
    REQUIRE(maps.texels.size() == 6 * perLayer);
    const ShadowMapTexels ground = *renderer().render(scene, groundCasts, {FrameOutput::ShadowMaps}).shadowMaps;
    const ShadowMapTexels none = *renderer().render(scene, noneCasts, {FrameOutput::ShadowMaps}).shadowMaps;
    long nearer = 0, farther = 0, drawn = 0;
    std::array<long, 6> silhouette{};
    for (std::size_t i = 0; i < maps.texels.size(); ++i) {
      drawn += maps.texels[i] < 1.0f;
      farther += maps.texels[i] > ground.texels[i];  // an object never pushes the ground back
      if (maps.texels[i] < ground.texels[i]) ++nearer, ++silhouette[i / perLayer];
    }
    CHECK(farther == 0);
    CHECK(nearer > 2000);                // the objects' silhouettes
    CHECK(silhouette[face] > nearer * 9 / 10);  // nearly all on the face below the light (the rest cross into its neighbours)
    CHECK(drawn > nearer);               // and the ground around them
    CHECK(maps.texels[centreTexel] < zCentre);  // the sphere's top, nearer the light than its centre
    CHECK(maps.texels[centreTexel] < ground.texels[centreTexel]);
    long untouched = 0;
    for (const float z : none.texels) untouched += z == 1.0f;
    CHECK(untouched == static_cast<long>(none.texels.size()));  // nothing casts: every texel 1
  }
}

TEST_CASE("shadow-map: reading the maps keeps them, and the next frame of the same pass 1 draws none") {
  const Scene scene = makeDefaultScene();
  RenderSettings settings = sized(64, 48);
  settings.shadows.mapSize = 128;
  const FrameInputs frame = buildFrameInputs(scene, settings);
  for (const auto& [name, make] : std::array<std::pair<const char*, std::function<std::unique_ptr<Renderer>()>>, 2>{
           {{"gl", [] { return makeGlRenderer(GlContextKind::OsMesa); }}, {"cpu", [] { return makeCpuRenderer(2); }}}}) {
    const std::string backend = name;
    CAPTURE(backend);
    const std::unique_ptr<Renderer> renderer = make();
    const ShadowMapTexels first = *renderer->render(scene, frame, {FrameOutput::ShadowMaps}).shadowMaps;
    const RenderResult result = renderer->render(scene, frame);
    bool kept = false;
    for (const PassTiming& t : result.timings) kept = kept || t.pass == shadowPassName(frame, true);
    CHECK(kept);
    CHECK(result.image == make()->render(scene, frame).image);  // the kept maps are the frame's
    CHECK(renderer->render(scene, frame, {FrameOutput::ShadowMaps}).shadowMaps->texels == first.texels);
  }
}

TEST_CASE("normals: the centre pixel of a sphere faces the eye") {
  const Scene scene = loadScene("builtin:sphere");
  for (const ShadingMode mode : {ShadingMode::Phong, ShadingMode::Gouraud, ShadingMode::Pbr, ShadingMode::Flat}) {
    RenderSettings settings = sized(161, 121);  // odd: the centre pixel's ray goes through the point looked at, the sphere's centre
    settings.shading = mode;
    const FrameInputs frame = buildFrameInputs(scene, settings);
    const glm::vec3 centre(frame.instances[0].worldFromModel[3]);
    const glm::vec3 towardEye = glm::normalize(frame.eyePosition - centre);
    // A 32-sided sphere: the interpolated normal is within a fraction of a degree, a flat facet within its half-width.
    const float minimumCosine = mode == ShadingMode::Flat ? 0.99f : 0.9995f;
    for (const auto& [name, renderer] : kBackends) {
      const std::string backend = name;
    CAPTURE(backend);
      CAPTURE(static_cast<int>(mode));
      const std::vector<glm::vec4> normals = *renderer().render(scene, frame, {FrameOutput::Normals}).normals;
      const glm::vec4 N = normals[pixelIndex(frame, frame.width / 2, frame.height / 2)];
      CHECK(N.w == 1.0f);
      CHECK(std::abs(glm::length(glm::vec3(N)) - 1.0f) < 1e-5f);
      CHECK(glm::dot(glm::vec3(N), towardEye) > minimumCosine);
      CHECK(normals[pixelIndex(frame, 0, 0)] == glm::vec4(0.0f));  // a corner shows no sphere
      // The picture: (N + 1)/2 in 8 bits, of N; within a level and a half of the eye's direction where N is (not flat's facet).
      const Image image = normalsImage(normals, frame.width, frame.height);
      const Rgba8 pixel = image.at(frame.width / 2, frame.height / 2);
      const auto level = [](float n) { return std::floor(255.0f * (n + 1.0f) * 0.5f + 0.5f); };
      CHECK(pixel == Rgba8{static_cast<std::uint8_t>(level(N.x)), static_cast<std::uint8_t>(level(N.y)), static_cast<std::uint8_t>(level(N.z)), 255});
      if (mode != ShadingMode::Flat) {
        const glm::vec3 expected = (towardEye + 1.0f) * 0.5f * 255.0f;
        CHECK(std::abs(pixel.r - expected.x) < 1.5f);
        CHECK(std::abs(pixel.g - expected.y) < 1.5f);
        CHECK(std::abs(pixel.b - expected.z) < 1.5f);
      }
      CHECK(image.at(0, 0) == Rgba8{0, 0, 0, 255});
    }
  }
}

TEST_CASE("normals: a back face drawn shows -N") {
  // The eye inside the sphere, culling off: every pixel is a back face, whose normal points at the eye's side of it.
  const Scene scene = loadScene("builtin:sphere");
  for (const ShadingMode mode : {ShadingMode::Phong, ShadingMode::Flat}) {
    RenderSettings settings = sized(64, 48);
    settings.shading = mode;
    settings.cullBackFaces = false;
    settings.camera.source = Source::Manual;
    settings.camera.eye = {0.1f, 0.0f, 0.0f};
    settings.camera.reference = {1.0f, 0.0f, 0.0f};
    settings.camera.near = 0.01f;
    settings.camera.far = 10.0f;
    const FrameInputs frame = buildFrameInputs(scene, settings);
    for (const auto& [name, renderer] : kBackends) {
      const std::string backend = name;
      CAPTURE(backend);
      CAPTURE(static_cast<int>(mode));
      const glm::vec4 N = (*renderer().render(scene, frame, {FrameOutput::Normals}).normals)[pixelIndex(frame, frame.width / 2, frame.height / 2)];
      CHECK(N.w == 1.0f);
      CHECK(N.x < -0.99f);  // the outward normal there is +x
    }
  }
}

TEST_CASE("light-0 of a one-light frame and the frame without lights add up to the frame, within one level") {
  // In linear light I = O_d·(k_a·I_a + d_0) + (k_e + s_0): light-0 is O_d·d_0 + s_0, the frame without
  // lights O_d·k_a·I_a + k_e. Each image holds its value rounded to an 8-bit sRGB level, off by at most
  // half that level's width; sRGB levels only widen with the value, so the sum of the two decoded levels
  // is within one level's width of the frame's value: one level at most, on covered pixels (the
  // background is in both).
  const Scene scene = makeDefaultScene();
  const SrgbTables& srgb = srgbTables();
  for (const ShadingMode mode : {ShadingMode::Phong, ShadingMode::Gouraud, ShadingMode::Flat}) {
    RenderSettings settings = sized(160, 120);
    settings.shading = mode;
    const FrameInputs frame = buildFrameInputs(scene, settings);
    REQUIRE(frame.lights.size() == 1);
    FrameInputs unlit = frame;
    unlit.lights.clear();
    unlit.shadowLayerCount = 0;
    for (const auto& [name, renderer] : kBackends) {
      const std::string backend = name;
    CAPTURE(backend);
      CAPTURE(static_cast<int>(mode));
      const Image full = renderer().render(scene, frame).image;
      const Image alone = renderStage(renderer(), scene, frame, parseStage("light-0")).image;
      const Image ambient = renderer().render(scene, unlit).image;
      const std::vector<std::uint32_t> kept = *renderer().render(scene, frame, {FrameOutput::TriangleIds}).triangleIds;
      int worst = 0;
      long covered = 0, darker = 0, brighter = 0;
      for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
          if (kept[pixelIndex(frame, x, y)] == 0) continue;
          ++covered;
          const Rgba8 f = full.at(x, y), a = alone.at(x, y), b = ambient.at(x, y);
          for (const auto& [cf, ca, cb] : {std::array<std::uint8_t, 3>{f.r, a.r, b.r}, {f.g, a.g, b.g}, {f.b, a.b, b.b}}) {
            const float sum = srgb.decoded[ca] + srgb.decoded[cb];
            worst = std::max(worst, std::abs(static_cast<int>(encodeLevel(sum)) - static_cast<int>(cf)));
            brighter += ca > cf;  // a light alone never outshines the frame it is part of
            darker += ca < cf;
          }
        }
      CHECK(covered > 5000);
      CHECK(worst <= 1);
      CHECK(brighter == 0);
      CHECK(darker > 2 * covered);  // the ambient light is gone almost everywhere
    }
  }
}

TEST_CASE("light-N: one light of two, its shadow maps first, the frame's other knobs untouched") {
  const Scene scene = makeDefaultScene();
  RenderSettings settings = sized(64, 48);
  settings = materialize(scene, settings, false, true);
  Light spot;
  spot.kind = LightKind::Spot;
  spot.position = {2.5f, 6.0f, 3.0f};
  spot.direction = {-0.35f, -1.0f, -0.45f};
  spot.spotCutoffDeg = 35.0f;
  settings.lights.insert(settings.lights.begin(), spot);
  settings.ambient = 0.2f;
  const FrameInputs frame = buildFrameInputs(scene, settings);
  REQUIRE(frame.lights.size() == 2);
  const FrameInputs alone = lightAlone(frame, 1);
  REQUIRE(alone.lights.size() == 1);
  CHECK(alone.lights[0].light.kind == LightKind::Point);
  CHECK(alone.lights[0].shadowLayer == 0);
  CHECK(alone.shadowLayerCount == 6);
  CHECK(alone.ambient == 0.0f);
  for (const CourseMaterial& m : alone.materials) CHECK(m.emissive == glm::vec3(0.0f));
  CHECK(alone.instances.size() == frame.instances.size());
  // Its maps are those the two-light frame draws for that light: layers 1-6 there.
  const ShadowMapTexels both = *cpuRenderer().render(scene, frame, {FrameOutput::ShadowMaps}).shadowMaps;
  const ShadowMapTexels one = *cpuRenderer().render(scene, alone, {FrameOutput::ShadowMaps}).shadowMaps;
  const std::size_t perLayer = static_cast<std::size_t>(both.size) * static_cast<std::size_t>(both.size);
  REQUIRE(both.layers == 7);
  CHECK(std::vector<float>(both.texels.begin() + static_cast<std::ptrdiff_t>(perLayer), both.texels.end()) == one.texels);
  CHECK_THROWS_AS(lightAlone(frame, 2), Error);
}

TEST_CASE("names parse and print, and a frame lists what it can show") {
  CHECK(parseStage("image") == Stage{StageKind::Image, 0});
  CHECK(parseStage("shadow-map") == Stage{StageKind::ShadowMap, 0});
  CHECK(parseStage("light-12") == Stage{StageKind::Light, 12});
  for (const char* name : {"image", "overdraw", "depth", "shadow-map", "normals", "light-0", "light-7"}) CHECK(stageName(parseStage(name)) == name);
  for (const char* bad : {"nosuch", "light", "light-", "light--1", "light-x", "light-1x", "light-+1", "Depth", "", "light-12345678901"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(parseStage(bad), UsageError);
  }
  CHECK_THROWS_WITH(parseStage("nosuch"), "--output-stage 'nosuch': expected image, overdraw, depth, shadow-map, normals or light-N (N = 0, 1, ...)");

  const Scene scene = makeDefaultScene();
  RenderSettings settings = sized(32, 24);
  FrameInputs frame = buildFrameInputs(scene, settings);
  CHECK(stageNames(frame) == std::vector<std::string>{"image", "overdraw", "depth", "shadow-map", "normals", "light-0"});
  CHECK_THROWS_WITH_AS(checkStage(frame, parseStage("light-3")), "--output-stage light-3: the frame has 1 light (light-0)", UsageError);
  settings.shadows.enabled = false;
  settings.hsr = HiddenSurface::Painter;
  frame = buildFrameInputs(scene, settings);
  CHECK(stageNames(frame) == std::vector<std::string>{"image", "overdraw", "normals", "light-0"});
  CHECK_THROWS_WITH(checkStage(frame, parseStage("shadow-map")),
                    "--output-stage shadow-map: the frame has no shadow maps: settings key 'shadows.enabled' is false");
  CHECK_THROWS_WITH(checkStage(frame, parseStage("depth")), doctest::Contains("settings key 'hsr': painter keeps no z-buffer"));
  CHECK_NOTHROW(checkStage(frame, parseStage("normals")));
}

TEST_CASE("the ray tracer and the readable reference refuse what they do not draw, by name") {
  const Scene scene = loadScene("builtin:cube");
  const FrameInputs frame = buildFrameInputs(scene, sized(16, 12));
  const std::unique_ptr<Renderer> ray = makeRayRenderer(1), reference = makeReferenceRenderer();
  CHECK_THROWS_WITH_AS(ray->render(scene, frame, {FrameOutput::Depth}), ("the depth stage is not drawn by " + ray->description()).c_str(), Error);
  CHECK_THROWS_WITH_AS(ray->render(scene, frame, {FrameOutput::ShadowMaps}), ("the shadow-map stage is not drawn by " + ray->description()).c_str(), Error);
  CHECK_THROWS_WITH_AS(reference->render(scene, frame, {FrameOutput::Normals}), ("the normals stage is not drawn by " + reference->description()).c_str(), Error);
  CHECK_THROWS_WITH_AS(renderStage(*ray, scene, frame, parseStage("depth")), doctest::Contains("the depth stage is not drawn by ray tracer"), Error);
  CHECK(renderStage(*ray, scene, frame, parseStage("light-0")).image.width() == 16);  // light-N is a frame: every backend draws it
}

TEST_CASE("the pictures' greys and colours") {
  // Depth: near white, far dark grey, nothing drawn black.
  const std::vector<float> depth = {1.0f, 0.5f, 0.75f, 0.625f};
  const Image grey = depthImage(depth, 2, 2);
  CHECK(grey.at(0, 0) == Rgba8{0, 0, 0, 255});
  CHECK(grey.at(1, 0) == Rgba8{255, 255, 255, 255});
  CHECK(grey.at(0, 1) == Rgba8{kFarGrey, kFarGrey, kFarGrey, 255});
  CHECK(grey.at(1, 1).r == 152);  // halfway: 48 + 207/2 = 151.5, rounded up
  // Normals: (N + 1)/2.
  const Image colours = normalsImage({glm::vec4(1, 0, 0, 1), glm::vec4(0, 0, -1, 1), glm::vec4(0), glm::vec4(std::nanf(""), 2, -2, 1)}, 2, 2);
  CHECK(colours.at(0, 0) == Rgba8{255, 128, 128, 255});
  CHECK(colours.at(1, 0) == Rgba8{128, 128, 0, 255});
  CHECK(colours.at(0, 1) == Rgba8{0, 0, 0, 255});
  CHECK(colours.at(1, 1) == Rgba8{0, 255, 0, 255});
}

TEST_CASE("a shadow-map strip wider than the largest image keeps every f-th texel") {
  ShadowMapTexels maps;
  maps.size = 400;
  maps.layers = 48;  // 19200 texels across: more than 16384
  maps.texels.assign(static_cast<std::size_t>(maps.size) * static_cast<std::size_t>(maps.size) * static_cast<std::size_t>(maps.layers), 1.0f);
  // Layer 5: one drawn texel at (2, 4), one at (3, 4) that a factor of 2 skips, and one farther at (10, 10).
  const auto at = [&](int layer, int x, int y) -> float& {
    return maps.texels[(static_cast<std::size_t>(layer) * 400 + static_cast<std::size_t>(y)) * 400 + static_cast<std::size_t>(x)];
  };
  at(5, 2, 4) = 0.5f;
  at(5, 3, 4) = 0.25f;
  at(5, 10, 10) = 0.75f;
  int factor = 0;
  const Image strip = shadowMapImage(maps, factor);
  CHECK(factor == 2);
  CHECK(strip.width() == 48 * 200);
  CHECK(strip.height() == 200);
  CHECK(strip.at(5 * 200 + 1, 2).r == 152);       // 0.5, halfway through layer 5's range [0.25, 0.75]
  CHECK(strip.at(5 * 200 + 5, 5).r == kFarGrey);  // 0.75, its far end
  CHECK(strip.at(4 * 200 + 1, 2).r == 0);         // layer 4: nothing drawn
  maps.size = 341;                                // 48 × 341 = 16368: whole
  maps.texels.assign(static_cast<std::size_t>(341) * 341 * 48, 1.0f);
  CHECK(shadowMapImage(maps, factor).width() == 16368);
  CHECK(factor == 1);
}
