#pragma once
// shading=pbr: glTF 2.0's metallic-roughness BRDF as the Khronos glTF Sample
// Viewer evaluates it, for one pixel (renderer/PIPELINE.md, "Shading",
// "Physically based"). Mirror: shaders/physically_based.glsl, the same
// functions in the same order with the same float operations.
//
//   L_o = Σ (S·f_att)·((N·L)·I_p)·((1 - F)·c_diff/π + F·D·Vis)
//       + ao·(c_diff·E(N)/π + prefiltered(R, r)·(F0·A + B)) + k_e
// D, Vis and x⁵ are pipeline/microfacet.h's, written once for float and double.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shading/environment.h"
#include "shading/lighting.h"
#include "shading/shading_math.h"
#include "shading/texture.h"
#include "pipeline/microfacet.h"
#include "pipeline/split_sum.h"

namespace facet {

inline constexpr float kDielectricF0 = 0.04f;  // a dielectric's reflectance at normal incidence

// What one pixel's material gives the BRDF.
struct PbrSurface {
  glm::vec3 baseColor;  // O_d, linear
  float metallic = 0;   // m
  float roughness = 1;  // r
  float occlusion = 1;  // ao: scales the ambient light
  glm::vec3 emissive{0.0f};  // k_e
};

// The pixel's surface: O_d as PIPELINE.md, "Textures", makes it, the material's factors
// times its maps, each read at its set's st[set] with derivatives d[set]
// (no texture transform) where the mesh has that set:
//   r·G, m·B of the metallic-roughness map; ao = 1 + strength·(R - 1); k_e·RGB of the emissive map.
inline PbrSurface pbrSurfaceAt(const Scene& scene, const CourseMaterial& m, const Mesh& mesh, glm::vec3 baseColor, const glm::vec2 (&st)[2],
                               const glm::vec4 (&d)[2]) {
  PbrSurface s{baseColor, m.metallic, m.roughness, 1.0f, m.emissive};
  const auto sample = [&](const MaterialMap& map) {
    const int set = map.set == 1 ? 1 : 0;
    return sampleTexture(scene.textures[static_cast<std::size_t>(map.texture)], map.sampler, st[set], d[set]);
  };
  if (readsMap(m.metallicRoughnessMap, mesh)) {
    const glm::vec4 t = sample(m.metallicRoughnessMap);
    s.roughness = s.roughness * t.g;
    s.metallic = s.metallic * t.b;
  }
  if (readsMap(m.occlusionMap, mesh)) s.occlusion = 1.0f + m.occlusionStrength * (sample(m.occlusionMap).r - 1.0f);
  if (const Texture* map = emissiveMapOf(scene, m, mesh)) {
    const int set = m.emissiveMap.set == 1 ? 1 : 0;
    s.emissive = emissionAt(*map, m, st[set], d[set]);
  }
  return s;
}

// F = F0 + (1 - F0)·x⁵, x = 1 - V·H (Schlick; both by pipeline/microfacet.h)
inline glm::vec3 schlickFresnel(glm::vec3 F0, float VdotH) { return schlickReflectance(F0, schlickWeight(VdotH)); }

// The split-sum factors (A, B) at roughness r and N·V: the table of
// pipeline/split_sum.h read LINEAR at x = N·V·31, y = r·31, indices clamped to [0, 31].
inline glm::vec2 environmentBrdf(float roughness, float NdotV) {
  const SplitSumTable& table = splitSumTable();
  const float x = NdotV * static_cast<float>(kSplitSumSize - 1), y = roughness * static_cast<float>(kSplitSumSize - 1);
  const float x0 = std::floor(x), y0 = std::floor(y);
  const float fx = x - x0, fy = y - y0;
  const auto index = [](float i) { return !(i >= 0.0f) ? 0 : (i > static_cast<float>(kSplitSumSize - 1) ? kSplitSumSize - 1 : static_cast<int>(i)); };
  const int i0 = index(x0), i1 = index(x0 + 1.0f), j0 = index(y0), j1 = index(y0 + 1.0f);
  const auto at = [&](int i, int j) { const glm::vec2 e = table.ab[static_cast<std::size_t>(j * kSplitSumSize + i)]; return glm::vec4(e, 0.0f, 0.0f); };
  return glm::vec2(lerp(lerp(at(i0, j0), at(i1, j0), fx), lerp(at(i0, j1), at(i1, j1), fx), fy));
}

// E(N)/π from the map's nine coefficients, each channel max(·, 0).
inline glm::vec3 irradianceAt(const EnvironmentMap& map, glm::vec3 N) {
  const auto& k = map.irradiance;
  const float x = N.x, y = N.y, z = N.z;
  const glm::vec3 e =
      ((((((((k[0] + k[1] * x) + k[2] * y) + k[3] * z) + k[4] * (x * y)) + k[5] * (y * z)) + k[6] * (x * z)) + k[7] * (x * x - y * y)) +
       k[8] * (z * z));
  return {maxZero(e.x), maxZero(e.y), maxZero(e.z)};
}

// The prefiltered radiance in R for roughness r: mip level r·q, trilinear between levels.
inline glm::vec3 prefilteredAt(const EnvironmentMap& map, glm::vec3 R, float roughness) {
  const int last = map.levelCount() - 1;
  const float lod = roughness * static_cast<float>(last);
  const float whole = std::floor(lod);
  const int k = whole < static_cast<float>(last) ? static_cast<int>(whole) : last;
  const glm::vec3 above = environmentAt(map, R, k);
  if (k == last) return above;
  return glm::vec3(lerp(glm::vec4(above, 0.0f), glm::vec4(environmentAt(map, R, k + 1), 0.0f), lod - whole));
}

// L_o at world point P with unit normal N and unit view vector V, linear and
// unclamped; S from `shadows` (shadow maps, or the ray tracer's shadow rays: lighting.h, illuminate).
template <class Shadows>
glm::vec3 shadePhysicallyBased(const FrameInputs& frame, const Shadows& shadows, const PbrSurface& s, glm::vec3 P, glm::vec3 N, glm::vec3 V) {
  const float m = s.metallic;
  const glm::vec3 cDiff = s.baseColor * (1.0f - m);
  const glm::vec3 F0 = glm::vec3(kDielectricF0 * (1.0f - m)) + s.baseColor * m;
  const float r2 = s.roughness * s.roughness;
  const float alpha = r2 > kMinAlpha ? r2 : kMinAlpha;
  const float alpha2 = alpha * alpha;
  const float NdotV = maxZero(dot3(N, V));
  const glm::vec3 lambert = cDiff / kPi;
  glm::vec3 color(0.0f);
  for (const FrameLight& fl : frame.lights) {
    const TowardLight<float> toward = towardLight<float>(fl, P);
    if (!toward.reaches) continue;
    const glm::vec3 L = toward.L;
    const float NdotL = dot3(N, L);
    if (!(NdotL > 0.0f)) continue;  // as the course's modes: nothing where N·L ≤ 0
    const glm::vec3 H = normalize3(L + V);
    const float NdotH = maxZero(dot3(N, H)), VdotH = maxZero(dot3(V, H));
    const glm::vec3 F = schlickFresnel(F0, VdotH);
    const float specular = ggxDistribution(NdotH, alpha2) * smithVisibility(NdotL, NdotV, alpha2);
    const glm::vec3 f = (glm::vec3(1.0f) - F) * lambert + F * specular;
    const float S = shadowFactorLanes(shadows, fl, frame.shadows, P, N, L, true);
    const glm::vec3 radiance = (S * toward.fAtt) * (NdotL * fl.intensity);
    color = color + radiance * f;
  }
  // Image-based ambient: the map's irradiance and prefiltered radiance, or I_a from every direction.
  const glm::vec2 ab = environmentBrdf(s.roughness, NdotV);
  const glm::vec3 specularWeight = F0 * ab.x + glm::vec3(ab.y);
  glm::vec3 diffuseLight(frame.ambient), specularLight(frame.ambient);
  if (frame.environment.map) {
    diffuseLight = irradianceAt(*frame.environment.map, N);
    const glm::vec3 R = (2.0f * dot3(N, V)) * N - V;
    specularLight = prefilteredAt(*frame.environment.map, R, s.roughness);
  }
  color = color + s.occlusion * (cDiff * diffuseLight + specularLight * specularWeight);
  return color + s.emissive;
}

}  // namespace facet
