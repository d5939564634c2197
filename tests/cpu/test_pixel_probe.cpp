// The picked pixel (cpu/pixel_probe.h): its numbers against the illumination
// equation written out here, for a pixel of a known triangle, and the colour
// its terms sum to against the pixel the backend drew.
#include <algorithm>
#include <cmath>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "cpu/pixel_probe.h"
#include "cpu_test_scenes.h"
#include "math/transforms.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/view_setup.h"
#include "scene/default_scene.h"
#include "scene/primitives.h"

using namespace facet;
using namespace facet::test;

namespace {

constexpr int kSize = 64;

bool near(glm::vec3 a, glm::vec3 b, float tolerance) { return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(tolerance))); }

// The ground y = 0 seen from above (parallel: V = +y everywhere), one point light, the course's coefficients set.
struct LitGround {
  Scene scene = groundScene(2, {0.8f, 0.3f, 0.2f});
  RenderSettings settings = topDownSettings(kSize);
  LitGround() {
    scene.materials[0].metallic = 0.0f;  // O_s = 1
    Light light;
    light.kind = LightKind::Point;
    light.position = {0.5f, 2.0f, 0.3f};
    light.color = {1.0f, 0.9f, 0.8f};
    light.intensity = 1.5f;
    light.attenuation = {1.0f, 0.1f, 0.0f};
    settings.lights = {light};
    settings.ambient = 0.3f;
    settings.material.ka = 0.2f;
    settings.material.kd = 0.7f;
    settings.material.ks = 0.5f;
    settings.material.shininess = 16.0f;
  }
};

}  // namespace

TEST_CASE("a probed pixel of the ground: P, N, V, L, H and every term of the illumination equation, as written out here") {
  for (const SpecularModel model : {SpecularModel::BlinnPhong, SpecularModel::Phong}) {
    for (const ShadingMode mode : {ShadingMode::Phong, ShadingMode::Flat}) {
      LitGround g;
      g.settings.specular = model;
      g.settings.shading = mode;
      const FrameInputs frame = buildFrameInputs(g.scene, g.settings);
      const int px = 41, py = 22;
      const PixelProbe probe = probePixel(g.scene, frame, px, py);
      CAPTURE(static_cast<int>(model));
      CAPTURE(static_cast<int>(mode));
      REQUIRE(probe.covered);
      CHECK(probe.weights.x + probe.weights.y + probe.weights.z == doctest::Approx(1.0f).epsilon(1e-6));
      for (int k = 0; k < 3; ++k) CHECK(probe.weights[k] >= -1e-6f);

      // Where the equation is evaluated: the pixel centre's point, or the triangle's centroid for flat shading.
      glm::vec3 P = worldAtPixel(px, py, kSize);
      if (mode == ShadingMode::Flat) P = (probe.vertices[0] + probe.vertices[1] + probe.vertices[2]) / 3.0f;
      CHECK(near(probe.P, P, 1e-5f));
      CHECK(near(probe.N, {0, 1, 0}, 1e-6f));
      CHECK(near(probe.V, {0, 1, 0}, 1e-6f));  // parallel projection: -k

      // I = k_e + k_a I_a O_d + f_att (k_d I_p (N.L) O_d + k_s I_p spec O_s), written out.
      const glm::vec3 Od{0.8f, 0.3f, 0.2f}, Os{1.0f}, Ip = glm::vec3(1.0f, 0.9f, 0.8f) * 1.5f, N{0, 1, 0}, V{0, 1, 0};
      const glm::vec3 toLight = glm::vec3(0.5f, 2.0f, 0.3f) - P;
      const float d = glm::length(toLight);
      const glm::vec3 L = toLight / d;
      const float fAtt = std::min(1.0f, 1.0f / (1.0f + 0.1f * d));
      const float NdotL = glm::dot(N, L);
      const glm::vec3 R = 2.0f * NdotL * N - L, H = glm::normalize(L + V);
      const float base = model == SpecularModel::Phong ? glm::dot(R, V) : glm::dot(N, H);
      const float spec = std::pow(std::max(base, 0.0f), 16.0f);
      const glm::vec3 ambient = 0.2f * 0.3f * Od;
      const glm::vec3 diffuse = fAtt * 0.7f * NdotL * Ip * Od, specular = fAtt * 0.5f * spec * Ip * Os;
      REQUIRE(probe.lights.size() == 1);
      const ProbedLight& l = probe.lights[0];
      CHECK(near(l.L, L, 1e-5f));
      CHECK(l.NdotL == doctest::Approx(NdotL).epsilon(1e-5));
      CHECK(l.fAtt == doctest::Approx(fAtt).epsilon(1e-5));
      CHECK(near(l.RorH, model == SpecularModel::Phong ? R : H, 1e-5f));
      CHECK(l.specularBase == doctest::Approx(base).epsilon(1e-5));
      // spec: the backends' own power (shading/shading_math.h, a series shared with the GLSL), not std::pow.
      CHECK(l.spec == doctest::Approx(spec).epsilon(1e-4));
      CHECK(l.lit);
      CHECK(!l.shadowMapped);
      CHECK(near(probe.ambient, ambient, 1e-6f));
      CHECK(near(l.diffuse, diffuse, 1e-5f));
      CHECK(near(l.specular, specular, 1e-4f));
      CHECK(near(probe.sum, ambient + diffuse + specular, 1e-4f));
      // The terms sum to what the lit pass computes, and that is the pixel drawn.
      CHECK(near(probe.sum, probe.shaded, 1e-5f));
      CHECK(probe.encoded == probe.drawn);
      CHECK(probe.drawn == expectedPixel(ambient + diffuse + specular));
    }
  }
}

TEST_CASE("a probed pixel in a cube's shadow: the texel read, the depth in it, the depth compared and the bias") {
  const Scene scene = occluderScene();
  Light light;
  light.kind = LightKind::Point;
  light.position = {0.0f, 3.0f, 0.0f};
  RenderSettings settings = shadowedTopDownSettings(kSize, light);
  settings.ambient = 0.1f;
  const FrameInputs frame = buildFrameInputs(scene, settings);
  // Under the cube, straight below the light: the ground is in shadow. Far out, it is lit.
  const PixelProbe shadowed = probePixel(scene, frame, kSize / 2, kSize / 2 + 1);
  REQUIRE(shadowed.covered);
  CHECK(shadowed.instance == 1);  // the cube's top, seen from above
  // x = 0.41 beside the cube (half-width 0.3), inside its shadow (half-width 0.3 * 3 / 1.9 = 0.47).
  const PixelProbe ground = probePixel(scene, frame, 38, 32);
  REQUIRE(ground.covered);
  CHECK(ground.instance == 0);
  const ProbedLight& l = ground.lights[0];
  CHECK(l.shadowMapped);
  CHECK(!l.outsideMap);
  CHECK(l.face == 3);  // -y: the light looks down at the ground
  CHECK(l.depthCompared - l.bias > l.depthRead);  // the cube is nearer the light than the ground point
  CHECK(l.S == 0.0f);
  CHECK(near(l.diffuse, glm::vec3(0.0f), 0.0f));
  const PixelProbe lit = probePixel(scene, frame, 3, 3);
  CHECK(lit.lights[0].S == 1.0f);
  CHECK(!(lit.lights[0].depthCompared - lit.lights[0].bias > lit.lights[0].depthRead));
  for (const PixelProbe* p : {&shadowed, &ground, &lit}) {
    CHECK(near(p->sum, p->shaded, 1e-5f));
    CHECK(p->encoded == p->drawn);
  }
}

TEST_CASE("probed pixels of the default scene: the terms sum to the lit pass's colour, encoded to the pixel drawn") {
  const Scene scene = makeDefaultScene();
  for (const ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
    RenderSettings settings;
    settings.width = 80;
    settings.height = 60;
    settings.shading = mode;
    settings.shadows.mapSize = 512;
    const FrameInputs frame = buildFrameInputs(scene, settings);
    int covered = 0, equal = 0, sums = 0;
    for (int y = 2; y < settings.height; y += 7)
      for (int x = 3; x < settings.width; x += 7) {
        const PixelProbe p = probePixel(scene, frame, x, y);
        if (!p.covered) continue;
        ++covered;
        equal += p.encoded == p.drawn;
        sums += mode == ShadingMode::Gouraud || glm::length(p.sum - p.shaded) <= 1e-5f * (1.0f + glm::length(p.shaded));
      }
    CAPTURE(static_cast<int>(mode));
    CHECK(covered > 40);
    CHECK(sums == covered);
    // Phong's P and N come from the probe's weights (double), not the rasterizer's planes: a level now and then.
    CHECK(equal >= covered * 9 / 10);
  }
  CHECK_THROWS_WITH(probePixel(scene, buildFrameInputs(scene, RenderSettings{}), 800, 0), doctest::Contains("outside the 800x600 frame"));
}
