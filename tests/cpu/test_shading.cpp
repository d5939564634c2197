// Lit colours at chosen pixels against the course's illumination equation,
// written out by hand here (not with the renderer's lighting code).
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "cpu_test_scenes.h"
#include "pipeline/material_coefficients.h"

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

// I = k_a·I_a·O_d + f_att·(k_d·I_p·max(N·L,0)·O_d + k_s·I_p·spec·O_s), O_s = (1 - m) + m·O_d,
// N = +y, V = +y (parallel, eye above).
glm::vec3 byHand(glm::vec3 P, const Light& light, SpecularModel model, float metallic = 0.0f, glm::vec3 base = kBase) {
  const glm::vec3 N{0, 1, 0}, V{0, 1, 0};
  glm::vec3 I = kKa * kIa * base;
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
  const glm::vec3 Os = (1.0f - metallic) + metallic * base;
  return I + fAtt * (kKd * Ip * NdotL * base + kKs * Ip * spec * Os);
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

TEST_CASE("materials: a metal's highlight has its base colour, a dielectric's the light's (O_s = (1 - m) + m·O_d)") {
  Light light = pointLight();
  light.position = {0.3f, 0.8f, 0.2f};  // the highlight in the image
  for (float m : {0.0f, 0.5f, 1.0f}) {
    CAPTURE(m);
    Scene scene = groundScene(4, kBase);
    scene.materials[0].metallic = m;
    const Image image = renderCpu(scene, handSettings(ShadingMode::Phong, SpecularModel::BlinnPhong, light));
    for (const auto& p : kProbes) checkPixel(image, p[0], p[1], byHand(worldAtPixel(p[0], p[1], kSize), light, SpecularModel::BlinnPhong, m));
  }
  // Under the highlight, the metal is tinted: its blue channel (O_d.b = 0.2) falls far below the dielectric's.
  Scene dielectric = groundScene(4, kBase), metal = groundScene(4, kBase);
  metal.materials[0].metallic = 1.0f;
  const int px = static_cast<int>((0.3f + 2.0f) / 4.0f * kSize), py = static_cast<int>((2.0f - 0.2f) / 4.0f * kSize);
  const Rgba8 white = renderCpu(dielectric, handSettings(ShadingMode::Phong, SpecularModel::BlinnPhong, light)).at(px, py);
  const Rgba8 tinted = renderCpu(metal, handSettings(ShadingMode::Phong, SpecularModel::BlinnPhong, light)).at(px, py);
  CHECK(white.b > tinted.b + 40);
  CHECK(white.r == tinted.r);  // O_d.r = 0.8 and the light's 1.0 both saturate red there
}

TEST_CASE("materials: glTF's defaults (metallic 1, roughness 1) give a red cube red, with n held to its minimum") {
  Material red;
  red.baseColor = {0.8f, 0.05f, 0.05f, 1.0f};  // metallic and roughness left at glTF's 1
  const CourseMaterial course = courseMaterial(red, {});
  CHECK(course.shininess == kMinDerivedShininess);
  CHECK(course.metallic == 1.0f);
  Material smooth = red;
  smooth.roughness = 0.2f;  // 2/α² - 2 = 1248, past the top
  CHECK(courseMaterial(smooth, {}).shininess == 1024.0f);
  // Rendered with its own coefficients, every lit pixel of the plane keeps red well above green and blue.
  Scene scene = groundScene(4, glm::vec3(red.baseColor));
  scene.materials[0] = red;
  RenderSettings s = topDownSettings(kSize);
  Light light = pointLight();
  light.position = {0.0f, 1.0f, 0.0f};
  s.lights = {light};
  s.shading = ShadingMode::Phong;
  const Image image = renderCpu(scene, s);
  int lit = 0;
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) {
      const Rgba8 c = image.at(px, py);
      if (c.r < 30) continue;
      ++lit;
      CAPTURE(px);
      CAPTURE(py);
      REQUIRE(c.g * 3 < c.r);
      REQUIRE(c.b * 3 < c.r);
    }
  CHECK(lit > kSize * kSize / 2);
}

TEST_CASE("vertex colours (COLOR_0) multiply the base colour in every shading mode") {
  const Light light = pointLight();
  const glm::vec3 vertexColor{0.5f, 1.0f, 0.25f};
  for (ShadingMode mode : {ShadingMode::Phong, ShadingMode::Gouraud, ShadingMode::Flat}) {
    CAPTURE(static_cast<int>(mode));
    Scene plain = groundScene(1, kBase * vertexColor);
    Scene colored = groundScene(1, kBase);
    colored.meshes[0].colors.assign(colored.meshes[0].positions.size(), glm::vec4(vertexColor, 1.0f));
    const Image want = renderCpu(plain, handSettings(mode, SpecularModel::BlinnPhong, light));
    const Image got = renderCpu(colored, handSettings(mode, SpecularModel::BlinnPhong, light));
    // The interpolated colour is c·(p·(1/p)), within an ulp of c: at most one level apart.
    int differing = 0;
    for (int py = 0; py < kSize; ++py)
      for (int px = 0; px < kSize; ++px) {
        const Rgba8 a = want.at(px, py), b = got.at(px, py);
        REQUIRE(std::abs(a.r - b.r) <= 1);
        REQUIRE(std::abs(a.g - b.g) <= 1);
        REQUIRE(std::abs(a.b - b.b) <= 1);
        differing += !(a == b);
      }
    CHECK(differing < kSize * kSize / 50);
  }
  // Varying colours vary: red at x = -2, blue at x = +2.
  Scene ramp = groundScene(1, glm::vec3(1.0f));
  for (const glm::vec3& p : ramp.meshes[0].positions)
    ramp.meshes[0].colors.push_back(p.x < 0.0f ? glm::vec4(1, 0, 0, 1) : glm::vec4(0, 0, 1, 1));
  const Image image = renderCpu(ramp, handSettings(ShadingMode::Phong, SpecularModel::BlinnPhong, light));
  CHECK(image.at(3, 32).r > image.at(3, 32).b + 50);
  CHECK(image.at(60, 32).b > image.at(60, 32).r + 50);
}

TEST_CASE("doubleSided: with culling on, a single-sided material's back faces are culled and a double-sided one's lit from behind") {
  Light below = pointLight();
  below.position = {0.2f, -1.5f, 0.1f};  // lights the plane's back side
  RenderSettings s = handSettings(ShadingMode::Phong, SpecularModel::BlinnPhong, below);
  s.camera.eye = {0, -10, 0};  // from below: the plane shows its back
  s.camera.up = {0, 0, 1};
  s.background = {0, 0, 0};
  for (bool doubleSided : {false, true})
    for (bool culling : {true, false})
      for (ShadingMode mode : {ShadingMode::Phong, ShadingMode::Gouraud, ShadingMode::Flat}) {
        CAPTURE(doubleSided);
        CAPTURE(culling);
        CAPTURE(static_cast<int>(mode));
        Scene scene = groundScene(4, kBase);
        scene.materials[0].doubleSided = doubleSided;
        s.cullBackFaces = culling;
        s.shading = mode;
        const Image image = renderCpu(scene, s);
        const Rgba8 centre = image.at(32, 32);
        if (culling && !doubleSided) {
          CHECK(centre == Rgba8{0, 0, 0, 255});
        } else {
          // Two-sided lighting: N = -y faces the light below, so the plane is lit, not ambient-dark.
          CHECK(centre.r > 100);
        }
      }
}
