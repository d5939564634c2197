// The course's 2-pass shadows on the CPU: in shadow behind an occluder, lit in
// front of it, and acne without bias.
#include <algorithm>
#include <cmath>
#include <set>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "../kept_shadow_maps.h"
#include "cpu/cpu_renderer.h"
#include "shading/lighting.h"
#include "shading/shadow_maps.h"
#include "cpu_test_scenes.h"
#include "math/transforms.h"
#include "scene/primitives.h"

using namespace facet;
using namespace facet::test;

namespace {

constexpr int kSize = 96;

RenderSettings shadowSettings(LightKind kind) {
  Light light;
  light.kind = kind;
  light.position = {-1.0f, 3.0f, 0.0f};
  light.direction = glm::normalize(glm::vec3(0.0f, 0.8f, 0.0f) - light.position);
  light.spotCutoffDeg = 45.0f;
  RenderSettings s = shadowedTopDownSettings(kSize, light);
  s.ambient = 0.1f;
  s.material.ka = 1.0f;
  s.material.kd = 1.0f;
  s.material.ks = 0.0f;
  return s;
}

// Pixel of world point (x, 0, z) in the top-down view.
std::array<int, 2> pixelOf(float x, float z) {
  return {static_cast<int>((x + 2.0f) / 4.0f * kSize), static_cast<int>((2.0f - z) / 4.0f * kSize)};
}

// 16x16 maps (`layers` of them) at depth 0.5 everywhere, and a shadow-casting light of `kind` whose
// shadow-map coordinates are the world's own: a point at z = 0.5 + d lies d behind the stored depth.
ShadowMaps constantMaps(int layers) {
  ShadowMaps maps;
  maps.reset(16, layers);
  std::fill(maps.depth.begin(), maps.depth.end(), 0.5f);
  return maps;
}

FrameLight identityLight(LightKind kind) {
  FrameLight light;
  light.light.kind = kind;
  light.hasShadowMap = true;
  light.shadowLayer = 0;
  light.shadowFromWorld.fill(glm::mat4(1.0f));
  return light;
}

}  // namespace

TEST_CASE("a ground point behind the occluder is in shadow, one in front of it is lit, for each light kind") {
  for (LightKind kind : {LightKind::Point, LightKind::Spot, LightKind::Directional}) {
    CAPTURE(static_cast<int>(kind));
    const RenderSettings s = shadowSettings(kind);
    const Image image = renderCpu(occluderScene(), s);
    // The light at (-1, 3, 0) through the cube centre (0, 0.8, 0) meets the ground at x = 0.36 (point, spot);
    // the directional light runs along the same direction.
    const auto shadowed = pixelOf(0.36f, 0.0f);
    const auto lit = pixelOf(-1.2f, 0.6f);
    const Rgba8 ambientOnly = expectedPixel(0.1f * glm::vec3(0.8f));
    CHECK(image.at(shadowed[0], shadowed[1]) == ambientOnly);
    CHECK(image.at(lit[0], lit[1]).r > ambientOnly.r + 60);
    // The whole shadow, not a sliver of it: the cube (x in ±0.3, y in [0.5, 1.1]) seen from
    // the light covers the ground row z = 0 from x = -0.16 to 1.05 (point, spot) or -0.07
    // to 0.8 (directional); the camera above sees the ground there for x > 0.3 (the cube's
    // top hides the rest), so x in [0.35, 0.75] is seen in shadow for every kind.
    for (float x = 0.35f; x <= 0.75f; x += 0.05f) {
      const auto p = pixelOf(x, 0.0f);
      CAPTURE(x);
      CHECK(image.at(p[0], p[1]) == ambientOnly);
    }
    RenderSettings off = s;
    off.shadows.enabled = false;
    CHECK(renderCpu(occluderScene(), off).at(shadowed[0], shadowed[1]).r > ambientOnly.r + 60);
  }
}

TEST_CASE("zero bias shows shadow acne on the lit ground and the contract's bias does not") {
  const auto darkLitGroundPixels = [](float slope, float minimum) {
    RenderSettings s = shadowSettings(LightKind::Spot);
    s.shadows.biasSlope = slope;
    s.shadows.biasMin = minimum;
    s.shadows.mapSize = 256;
    const Image image = renderCpu(occluderScene(), s);
    const Rgba8 ambientOnly = expectedPixel(0.1f * glm::vec3(0.8f));
    int dark = 0;
    // Ground with x in [-1.66, -0.65] and z in [-0.77, 0.73]: inside the 45° cone
    // (dot(-L, D) >= 0.77), far from the cube's shadow around x = 0.36.
    for (int py = 30; py < 66; ++py)
      for (int px = 8; px < 33; ++px)
        if (image.at(px, py) == ambientOnly) ++dark;
    return dark;
  };
  const RenderSettings defaults;
  const int acne = darkLitGroundPixels(0.0f, 0.0f);
  const int clean = darkLitGroundPixels(defaults.shadows.biasSlope, defaults.shadows.biasMin);
  CHECK(acne > 200);
  CHECK(clean == 0);
}

TEST_CASE("PCF softens the shadow edge: intermediate values appear that hard shadows lack") {
  const auto distinctReds = [](int radius) {
    RenderSettings s = shadowSettings(LightKind::Spot);
    s.shadows.pcfRadius = radius;
    s.shadows.mapSize = 128;
    const Image image = renderCpu(occluderScene(), s);
    std::set<int> reds;
    for (int py = 0; py < kSize; ++py)
      for (int px = kSize / 2; px < kSize * 3 / 4; ++px) reds.insert(image.at(px, py).r);
    return reds.size();
  };
  CHECK(distinctReds(2) > distinctReds(0) + 5);
}

TEST_CASE("the shadow bias is max(b_slope·(1 - N·L), b_min): a point just beyond it is in shadow, one just within it is lit") {
  // One directional light whose shadow-map coordinates are the world's own (u, v, z) = (x, y, z), and a
  // 16x16 map holding depth 0.5 everywhere: a point at z = 0.5 + d is in shadow exactly when d > bias.
  const FrameLight light = identityLight(LightKind::Directional);
  const ShadowMaps maps = constantMaps(1);
  ShadowSettings shadows;
  shadows.pcfRadius = 0;
  shadows.biasMin = 0.01f;
  const glm::vec3 L{0.0f, 0.0f, 1.0f};
  const auto S = [&](float d, glm::vec3 N, float slope) {
    shadows.biasSlope = slope;
    return shadowFactor(maps, light, shadows, {0.5f, 0.5f, 0.5f + d}, N, L);
  };
  const glm::vec3 facing{0.0f, 0.0f, 1.0f};  // N·L = 1: the slope term is 0, b_min decides
  CHECK(S(0.0099f, facing, 0.04f) == 1.0f);
  CHECK(S(0.0101f, facing, 0.04f) == 0.0f);
  const glm::vec3 grazing = glm::normalize(glm::vec3(0.0f, 1.0f, 1.0f / std::sqrt(3.0f)));  // N·L = 0.5: b_slope·0.5 = 0.02 > b_min
  CHECK(S(0.0195f, grazing, 0.04f) == 1.0f);
  CHECK(S(0.0205f, grazing, 0.04f) == 0.0f);
  CHECK(S(0.0205f, grazing, 0.0f) == 0.0f);  // without the slope term, b_min = 0.01 again
  CHECK(S(-0.1f, grazing, 0.04f) == 1.0f);   // nearer the light than the map: lit
}

TEST_CASE("PCF taps beyond a map's edge: lit for a spot or directional map, the edge texel for a point light's cube face") {
  // Shadow-map coordinates are the world's own, a 16x16 map at depth 0.5 and a point at z = 0.6 behind
  // it at u = 0.99, in the last column: a 3x3 kernel has three taps in column 16, beyond the edge.
  const ShadowMaps maps = constantMaps(6);
  ShadowSettings shadows;
  shadows.pcfRadius = 1;
  shadows.biasMin = 0.01f;
  shadows.biasSlope = 0.0f;
  const glm::vec3 P{0.99f, 0.5f, 0.6f}, N{0.0f, 0.0f, 1.0f}, L{0.0f, 0.0f, 1.0f};
  const auto S = [&](LightKind kind) {
    FrameLight light = identityLight(kind);
    light.light.position = {-10.0f, 0.5f, 0.5f};  // P - position lies along +x: cube face 0
    return shadowFactor(maps, light, shadows, P, N, L);
  };
  CHECK(S(LightKind::Directional) == doctest::Approx(3.0f / 9.0f));
  CHECK(S(LightKind::Spot) == doctest::Approx(3.0f / 9.0f));
  // The neighbouring cube face holds what lies beyond the edge: no lit seam where the face changes.
  CHECK(S(LightKind::Point) == 0.0f);
}

TEST_CASE("the CPU renderer keeps its shadow maps while the light, the geometry and the shadow settings stay, and redraws them when they change") {
  checkShadowMapsKept([] { return makeCpuRenderer(2); });
}
