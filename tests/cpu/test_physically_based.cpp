// shading=pbr (renderer/PIPELINE.md, "Physically based"): the
// microfacet terms integrate as the physics says, the split-sum table holds
// what the BRDF reflects, a map's irradiance is its cosine integral, and
// metals tint their reflection while dielectrics do not.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "shading/physically_based.h"
#include "image/srgb.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/microfacet.h"
#include "scene/default_scene.h"
#include "scene/environment_map.h"

using namespace facet;

namespace {

constexpr double kPiDouble = std::numbers::pi;

// Σ f(l)·dω over the hemisphere around +z by the midpoint rule in (θ, φ).
template <class F>
double hemisphere(int steps, F f) {
  double sum = 0.0;
  const double dTheta = 0.5 * kPiDouble / steps, dPhi = kPiDouble / steps;
  for (int i = 0; i < steps; ++i) {
    const double theta = (i + 0.5) * dTheta;
    for (int j = 0; j < 2 * steps; ++j) {
      const double phi = (j + 0.5) * dPhi;
      const glm::dvec3 l(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      sum += f(l) * std::sin(theta) * dTheta * dPhi;
    }
  }
  return sum;
}

// The unit direction through the centre of texel (x, y) (bottom row first) of a face of an n-texel cube.
glm::dvec3 texelDirection(int face, int x, int y, int n) {
  const double a = 2.0 * (x + 0.5) / n - 1.0, b = 2.0 * (1.0 - (y + 0.5) / n) - 1.0;  // sc/ma, tc/ma
  const glm::dvec3 d[6] = {{1, -b, -a}, {-1, -b, a}, {a, 1, b}, {a, -1, -b}, {a, -b, 1}, {-a, -b, -1}};
  return glm::normalize(d[face]);
}

// A cube map whose grey texels encode radiance(direction), 8 bits as every map.
template <class F>
EnvironmentMap mapOf(int n, F radiance) {
  Image strip(6 * n, n);
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const std::uint8_t level = encodeLevel(static_cast<float>(radiance(texelDirection(f, x, y, n))));
        strip.at(f * n + x, y) = {level, level, level, 255};
      }
  return environmentMapOf(std::move(strip), "test map");
}

// E(N)/π of the map's texels by brute force: Σ L·max(N·d, 0)·dω / π.
double irradianceByTexels(const EnvironmentMap& map, glm::dvec3 N) {
  const int n = map.faceSize();
  const float* decoded = srgbTables().decoded.data();
  double sum = 0.0;
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double a = 2.0 * (x + 0.5) / n - 1.0, b = 2.0 * (1.0 - (y + 0.5) / n) - 1.0, r2 = 1.0 + a * a + b * b;
        const double dw = (4.0 / (n * n)) / (r2 * std::sqrt(r2));
        sum += decoded[map.faces.at(f * n + x, y).r] * std::max(0.0, glm::dot(N, texelDirection(f, x, y, n))) * dw;
      }
  return sum / kPiDouble;
}

}  // namespace

TEST_CASE("pbr: GGX's D is a distribution of normals: D times N.H integrates to 1 over the hemisphere at every roughness") {
  for (const double alpha : {0.1, 0.3, 0.6, 1.0}) {
    const double integral = hemisphere(1500, [&](const glm::dvec3& h) { return ggxDistribution(h.z, alpha * alpha) * h.z; });
    CAPTURE(alpha);
    CHECK(integral == doctest::Approx(1.0).epsilon(2e-3));
  }
}

TEST_CASE("pbr: the split-sum table holds the BRDF's own directional albedo, 1 - ln 2 for a rough metal seen head-on") {
  // F = 1, r = 1 (α = 1): D = 1/π and Vis = 0.5/(N.L + N.V), so at N.V = 1 the albedo is ∫ μ/(1 + μ) dμ = 1 - ln 2.
  const glm::vec2 rough = environmentBrdf(1.0f, 1.0f);
  CHECK(rough.x + rough.y == doctest::Approx(1.0 - std::log(2.0)).epsilon(0.01));
  // Both factors against the hemisphere integral of D·Vis·(N·L), split by x⁵, at table points.
  for (const double r : {9.0 / 31, 18.0 / 31, 25.0 / 31, 1.0})
    for (const double nv : {9.0 / 31, 19.0 / 31, 1.0}) {
      const double alpha = r * r, a2 = alpha * alpha;
      const glm::dvec3 v(std::sqrt(1.0 - nv * nv), 0.0, nv);
      const auto part = [&](bool fresnel) {
        return hemisphere(600, [&](const glm::dvec3& l) {
          const glm::dvec3 h = glm::normalize(l + v);
          const double x5 = schlickWeight(glm::dot(v, h));
          return (fresnel ? x5 : 1.0 - x5) * ggxDistribution(h.z, a2) * smithVisibility(l.z, nv, a2) * l.z;
        });
      };
      const glm::vec2 ab = environmentBrdf(static_cast<float>(r), static_cast<float>(nv));
      CAPTURE(r);
      CAPTURE(nv);
      CHECK(std::fabs(ab.x - part(false)) < 0.01);
      CHECK(std::fabs(ab.y - part(true)) < 0.005);
    }
}

TEST_CASE("pbr: a map's irradiance is its cosine-weighted integral: a constant sky's value, a quadratic sky's exactly, a sun's within 0.005") {
  const EnvironmentMap grey = mapOf(8, [](const glm::dvec3&) { return 0.5; });
  const float half = srgbTables().decoded[encodeLevel(0.5f)];
  for (const glm::vec3 N : {glm::vec3(0, 1, 0), glm::vec3(0.6f, 0, 0.8f), glm::vec3(0, 0, -1)})
    CHECK(irradianceAt(grey, N).r == doctest::Approx(half).epsilon(1e-4));
  // Quadratic skies are within the nine harmonics: E/π is theirs up to the texels' 8 bits.
  const EnvironmentMap linear = mapOf(32, [](const glm::dvec3& d) { return 0.4 + 0.3 * d.y + 0.1 * d.x * d.z; });
  // A sun 25° across: far from quadratic, so the nine harmonics approximate it (Ramamoorthi and Hanrahan bound
  // the error of any sky by 9 % of the irradiance's range, and the cosine's high orders are small).
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  const EnvironmentMap lit = mapOf(32, [&](const glm::dvec3& d) { return glm::dot(d, sun) > std::cos(12.5 * kPiDouble / 180.0) ? 1.0 : 0.05; });
  double worstLinear = 0.0, worstLit = 0.0;
  for (const glm::dvec3 N : {glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0), glm::normalize(glm::dvec3(1, 1, 1)),
                             glm::normalize(glm::dvec3(-1, 0.3, 2))}) {
    worstLinear = std::max(worstLinear, std::fabs(irradianceAt(linear, glm::vec3(N)).r - irradianceByTexels(linear, N)));
    worstLit = std::max(worstLit, std::fabs(irradianceAt(lit, glm::vec3(N)).r - irradianceByTexels(lit, N)));
  }
  MESSAGE("irradiance: worst |SH - texels| ", worstLinear, " (quadratic sky), ", worstLit, " (a sun)");
  CHECK(worstLinear < 2e-3);
  CHECK(worstLit < 0.005);  // measured 0.0015, 1.5 % of the sun's peak irradiance of 0.1
}

TEST_CASE("pbr: a metal's light takes its base colour, a dielectric's highlight keeps the light's, and roughness widens the lobe") {
  Scene scene = makeDefaultScene();
  RenderSettings settings;
  settings.shading = ShadingMode::Pbr;
  settings.shadows.enabled = false;
  settings.ambient = 0.0f;
  FrameInputs frame = buildFrameInputs(scene, settings);
  frame.lights.resize(1);
  frame.lights[0].light.kind = LightKind::Directional;
  frame.lights[0].light.direction = {0, 0, -1};
  frame.lights[0].intensity = glm::vec3(1.0f);
  frame.lights[0].hasShadowMap = false;
  const ShadowMaps none;
  const glm::vec3 P(0.0f), N(0, 0, 1), V(0, 0, 1), gold(1.0f, 0.6f, 0.2f);
  const glm::vec3 metal = shadePhysicallyBased(frame, none, {gold, 1.0f, 0.4f, {}}, P, N, V);
  CHECK(metal.g / metal.r == doctest::Approx(0.6).epsilon(1e-5));
  CHECK(metal.b / metal.r == doctest::Approx(0.2).epsilon(1e-5));
  // A dielectric: Lambert's colour (1 - F)·c_diff/π plus a grey lobe, the same in every channel.
  const glm::vec3 plastic = shadePhysicallyBased(frame, none, {gold, 0.0f, 0.4f, {}}, P, N, V);
  const glm::vec3 lambert = gold * (0.96f / kPi);
  const float lobe = plastic.r - lambert.r;
  CHECK(lobe > 0.0f);
  CHECK(plastic.g - lambert.g == doctest::Approx(lobe).epsilon(1e-4));
  CHECK(plastic.b - lambert.b == doctest::Approx(lobe).epsilon(1e-4));
  // Roughness spreads the lobe: at 30° off the mirror a rough metal is brighter than a smooth one, at the mirror darker.
  const glm::vec3 tilted = glm::normalize(glm::vec3(0.5f, 0.0f, 0.866f));
  const float smoothAt = shadePhysicallyBased(frame, none, {gold, 1.0f, 0.2f, {}}, P, N, N).r;
  const float roughAt = shadePhysicallyBased(frame, none, {gold, 1.0f, 0.8f, {}}, P, N, N).r;
  const float smoothOff = shadePhysicallyBased(frame, none, {gold, 1.0f, 0.2f, {}}, P, N, tilted).r;
  const float roughOff = shadePhysicallyBased(frame, none, {gold, 1.0f, 0.8f, {}}, P, N, tilted).r;
  CHECK(smoothAt > roughAt);
  CHECK(roughOff > smoothOff);
}

TEST_CASE("pbr: the maps scale roughness by G and metallic by B as data, occlusion by strength, and k_e by the emissive colour") {
  Scene scene;
  const auto texture = [&](Rgba8 c, TexelEncoding encoding) {
    Texture t;
    t.image = Image(1, 1, c);
    t.encoding = encoding;
    scene.textures.push_back(t);
    return static_cast<int>(scene.textures.size() - 1);
  };
  CourseMaterial m;
  m.metallic = 0.5f, m.roughness = 0.8f, m.emissive = glm::vec3(2.0f), m.occlusionStrength = 0.5f;
  m.metallicRoughnessMap.texture = texture({0, 128, 255, 255}, TexelEncoding::Linear);
  m.occlusionMap.texture = texture({64, 0, 0, 255}, TexelEncoding::Linear);
  m.emissiveMap.texture = texture({255, 128, 0, 255}, TexelEncoding::Srgb);
  Mesh mesh;
  mesh.texcoords = {{0.5f, 0.5f}};
  const PbrSurface s = pbrSurfaceAt(scene, m, mesh, glm::vec3(1.0f), {glm::vec2(0.5f), glm::vec2(0.5f)}, {glm::vec4(0.0f), glm::vec4(0.0f)});
  CHECK(s.roughness == doctest::Approx(0.8 * 128.0 / 255.0));
  CHECK(s.metallic == doctest::Approx(0.5));
  CHECK(s.occlusion == doctest::Approx(1.0 + 0.5 * (64.0 / 255.0 - 1.0)));
  CHECK(s.emissive.r == doctest::Approx(2.0));
  CHECK(s.emissive.g == doctest::Approx(2.0 * srgbTables().decoded[128]));  // colour: decoded, not 128/255
  CHECK(s.emissive.b == 0.0f);
  // Without texture coordinates the maps are not read: the factors alone.
  const PbrSurface bare = pbrSurfaceAt(scene, m, Mesh{}, glm::vec3(1.0f), {glm::vec2(0.5f), glm::vec2(0.5f)}, {glm::vec4(0.0f), glm::vec4(0.0f)});
  CHECK(bare.roughness == 0.8f);
  CHECK(bare.occlusion == 1.0f);
}
