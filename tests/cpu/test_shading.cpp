// Lit colours at chosen pixels against the course's illumination equation,
// written out by hand here (not with the renderer's lighting code).
#include <cmath>
#include <cstdlib>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "cpu_test_scenes.h"

using namespace facet;
using namespace facet::test;

namespace {

constexpr int kSize = 64;
const glm::vec3 kBase{0.8f, 0.5f, 0.2f};
constexpr float kKa = 0.3f, kKd = 0.7f, kKs = 0.5f, kN = 20.0f, kIa = 0.1f;

RenderSettings handSettings(ShadingMode mode, SpecularModel specular, const Light& light) {
  RenderSettings s = topDownSettings(kSize);
  s.shading = mode;
  s.specular = specular;
  s.ambient = kIa;
  s.material.ka = kKa;
  s.material.kd = kKd;
  s.material.ks = kKs;
  s.material.shininess = kN;
  s.lights = {light};
  return s;
}

// I = k_a·I_a·O_d + f_att·(k_d·I_p·max(N·L,0)·O_d + k_s·I_p·spec), N = +y, V = +y (parallel, eye above).
glm::vec3 byHand(glm::vec3 P, const Light& light, SpecularModel model) {
  const glm::vec3 N{0, 1, 0}, V{0, 1, 0};
  glm::vec3 I = kKa * kIa * kBase;
  glm::vec3 L;
  float fAtt = 1.0f;
  if (light.kind == LightKind::Directional) {
    L = -glm::normalize(light.direction);
  } else {
    const float d = glm::length(light.position - P);
    L = (light.position - P) / d;
    fAtt = std::min(1.0f, 1.0f / (light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d * d));
    if (light.kind == LightKind::Spot && !(glm::dot(-L, glm::normalize(light.direction)) > std::cos(glm::radians(light.spotCutoffDeg))))
      return I;
  }
  const float NdotL = glm::dot(N, L);
  if (NdotL <= 0.0f) return I;
  float spec;
  if (model == SpecularModel::Phong) {
    const glm::vec3 R = 2.0f * NdotL * N - L;
    spec = std::pow(std::max(glm::dot(R, V), 0.0f), kN);
  } else {
    spec = std::pow(std::max(glm::dot(N, glm::normalize(L + V)), 0.0f), kN);
  }
  const glm::vec3 Ip = light.color * light.intensity;
  return I + fAtt * (kKd * Ip * NdotL * kBase + kKs * Ip * spec);
}

void checkPixel(const Image& image, int px, int py, glm::vec3 linear) {
  const Rgba8 got = image.at(px, py), want = expectedPixel(linear);
  CAPTURE(px);
  CAPTURE(py);
  CHECK(std::abs(got.r - want.r) <= 1);
  CHECK(std::abs(got.g - want.g) <= 1);
  CHECK(std::abs(got.b - want.b) <= 1);
}

Light pointLight() {
  Light l;
  l.kind = LightKind::Point;
  l.position = {0.4f, 1.5f, -0.3f};
  l.attenuation = {1.0f, 0.1f, 0.05f};
  l.color = {1.0f, 0.9f, 0.8f};
  l.intensity = 1.2f;
  l.castsShadow = false;
  return l;
}

// Pixels spread over the image, away from the highlight's steepest part.
const int kProbes[][2] = {{5, 7}, {20, 40}, {33, 30}, {50, 12}, {60, 58}, {31, 33}};

}  // namespace

TEST_CASE("Phong shading matches the equation at every probe, for each specular model and light kind") {
  const Scene scene = groundScene(4, kBase);
  Light directional = pointLight();
  directional.kind = LightKind::Directional;
  directional.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, 0.5f));
  Light spot = pointLight();
  spot.kind = LightKind::Spot;
  spot.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, 0.1f));
  spot.spotCutoffDeg = 35.0f;
  for (const Light& light : {pointLight(), directional, spot})
    for (SpecularModel model : {SpecularModel::Phong, SpecularModel::BlinnPhong}) {
      CAPTURE(static_cast<int>(light.kind));
      CAPTURE(static_cast<int>(model));
      const Image image = renderCpu(scene, handSettings(ShadingMode::Phong, model, light));
      for (const auto& p : kProbes) checkPixel(image, p[0], p[1], byHand(worldAtPixel(p[0], p[1], kSize), light, model));
    }
}

TEST_CASE("a spot light lights inside its cone only") {
  Light spot = pointLight();
  spot.kind = LightKind::Spot;
  spot.position = {0, 2, 0};
  spot.direction = {0, -1, 0};
  spot.spotCutoffDeg = 20.0f;  // radius 2·tan 20° = 0.73 on the ground
  const Image image = renderCpu(groundScene(2, kBase), handSettings(ShadingMode::Phong, SpecularModel::BlinnPhong, spot));
  checkPixel(image, 32, 32, byHand(worldAtPixel(32, 32, kSize), spot, SpecularModel::BlinnPhong));
  checkPixel(image, 2, 2, kKa * kIa * kBase);  // far outside the cone: ambient only
  CHECK(image.at(32, 32).r > image.at(2, 2).r + 50);
}

TEST_CASE("flat shading: one colour per triangle, lit at its centroid with its geometric normal") {
  // makePlane(1) scaled by 2: corners (±2, 0, ±2), split along one diagonal.
  const Light light = pointLight();
  const Image image = renderCpu(groundScene(1, kBase), handSettings(ShadingMode::Flat, SpecularModel::BlinnPhong, light));
  // Find the two colours: sample two pixels on opposite sides of each diagonal and match centroids.
  const glm::vec3 corners[4] = {{-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}};
  int matched = 0;
  for (const auto& p : {std::array{4, 20}, std::array{20, 4}, std::array{59, 43}, std::array{43, 59}}) {
    const Rgba8 got = image.at(p[0], p[1]);
    // Every triangle of a diagonal split has its centroid at 2/3 of the way toward one of the corners.
    bool ok = false;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        for (int c = b + 1; c < 4; ++c) {
          const glm::vec3 centroid = (corners[a] + corners[b] + corners[c]) / 3.0f;
          const Rgba8 want = expectedPixel(byHand(centroid, light, SpecularModel::BlinnPhong));
          if (std::abs(got.r - want.r) <= 1 && std::abs(got.g - want.g) <= 1 && std::abs(got.b - want.b) <= 1) ok = true;
        }
    matched += ok;
  }
  CHECK(matched == 4);
  // Uniform inside a triangle: two pixels deep inside the same corner region agree exactly.
  CHECK(image.at(2, 30) == image.at(4, 40));
}

TEST_CASE("Gouraud shading: vertex colours by the equation, interpolated across the triangle") {
  // One quad, two triangles; the parallel view makes screen weights equal world weights.
  const Light light = pointLight();
  const Image image = renderCpu(groundScene(1, kBase), handSettings(ShadingMode::Gouraud, SpecularModel::Phong, light));
  // Pixel (40, 10): world (0.5625, 0, 1.3125). The quad's vertices come from makePlane's grid
  // (u, v) -> (2u-1, 0, 2v-1)·2 with triangles (c,r+1),(c+1,r+1),(c+1,r) and (c,r+1),(c+1,r),(c,r):
  // A = (-2,0,2), B = (2,0,2), C = (2,0,-2) holds points with x > -z... test by barycentrics.
  const glm::vec3 A{-2, 0, 2}, B{2, 0, 2}, C{2, 0, -2}, D{-2, 0, -2};
  for (const auto& p : {std::array{40, 10}, std::array{10, 40}, std::array{50, 30}, std::array{15, 12}}) {
    const glm::vec3 P = worldAtPixel(p[0], p[1], kSize);
    // Triangle ABC when x >= -z (below the A-C diagonal), else triangle ACD.
    const bool first = P.x >= -P.z;
    const glm::vec3 a = A, b = first ? B : C, c = first ? C : D;
    const auto area = [](glm::vec3 u, glm::vec3 v, glm::vec3 w) { return (v.x - u.x) * (w.z - u.z) - (w.x - u.x) * (v.z - u.z); };
    const float total = area(a, b, c);
    const float la = area(P, b, c) / total, lb = area(a, P, c) / total, lc = area(a, b, P) / total;
    const glm::vec3 colour = la * byHand(a, light, SpecularModel::Phong) + lb * byHand(b, light, SpecularModel::Phong) +
                             lc * byHand(c, light, SpecularModel::Phong);
    checkPixel(image, p[0], p[1], colour);
  }
}

TEST_CASE("Phong and Gouraud differ where the highlight falls between vertices") {
  // The highlight under the light sits inside the single quad's cells: per-vertex
  // lighting misses its peak, per-pixel lighting does not.
  Light light = pointLight();
  light.position = {0.3f, 0.8f, 0.2f};
  const Image phong = renderCpu(groundScene(1, kBase), handSettings(ShadingMode::Phong, SpecularModel::Phong, light));
  const Image gouraud = renderCpu(groundScene(1, kBase), handSettings(ShadingMode::Gouraud, SpecularModel::Phong, light));
  const int px = static_cast<int>((0.3f + 2.0f) / 4.0f * kSize), py = static_cast<int>((2.0f - 0.2f) / 4.0f * kSize);
  CHECK(phong.at(px, py).g > gouraud.at(px, py).g + 20);
}
