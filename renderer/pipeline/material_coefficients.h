#pragma once
#include <glm/vec3.hpp>

#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

// A texture a material reads besides its base colour (shading=pbr's maps).
struct MaterialMap {
  int texture = -1;  // index into Scene::textures, -1 = none
  Sampler sampler;   // its sampler with textures.filter applied
  bool srgb = false; // its texels are read as sRGB colour (a texture a file also uses as colour), not as data
  int set = 0;       // the texture coordinates it reads: TEXCOORD_0 or TEXCOORD_1
};

// A material in the course's terms: the coefficients of
//   I = k_e + k_a·I_a·O_d + Σ S·f_att·(k_d·I_p·max(N·L, 0)·O_d + k_s·I_p·spec·O_s), spec = (·)^n
// with the specular colour O_s = (1 - m) + m·O_d: the light's colour for a
// dielectric, the base colour for a metal.
struct CourseMaterial {
  glm::vec3 baseColor{1.0f};  // O_d, linear RGB (multiplied by the texture when there is one)
  int baseColorTexture = -1;  // index into Scene::textures, -1 = none
  Sampler baseColorSampler;   // its sampler with textures.filter applied (pipeline/texture_filter.h)
  int baseColorSet = 0;       // the texture coordinates it reads: TEXCOORD_0 or TEXCOORD_1
  // Its KHR_texture_transform as the rows of a 2×3 matrix: (s', t') = ((r0.x·s + r0.y·t) + r0.z, (r1.x·s + r1.y·t) + r1.z).
  glm::vec3 uvRow0{1.0f, 0.0f, 0.0f}, uvRow1{0.0f, 1.0f, 0.0f};
  glm::vec3 emissive{0.0f};   // k_e, linear RGB
  float ka = 0, kd = 0, ks = 0;
  float shininess = 1;        // n
  float metallic = 0;         // m in O_s = (1 - m) + m·O_d, in [0, 1]
  float roughness = 1;        // r, in [0, 1]: shading=pbr's (PIPELINE.md, "Shading")
  // shading=pbr's maps (PIPELINE.md, "Shading"): G and B scale r and m, R is the ambient occlusion, RGB scales k_e.
  MaterialMap metallicRoughnessMap, occlusionMap, emissiveMap;
  float occlusionStrength = 1;  // ao = 1 + strength·(R - 1)
  // A glTF normal texture, tangent space (PIPELINE.md, "Textures"): Phong and pbr read it per pixel.
  MaterialMap normalMap;
  float normalScale = 1;        // scales its x and y
  bool doubleSided = false;
  // Alpha (PIPELINE.md, "Textures"): α = factor·COLOR_0.a·texel.a, each where present;
  // with `masked`, a fragment is kept when α ≥ alphaCutoff (NaN discards).
  float baseAlpha = 1.0f;     // the base colour factor's alpha (material.opacity in its place)
  bool masked = false;
  // Transparency (PIPELINE.md, "Shading"): blended into the colour buffer by
  // α after the opaque surfaces; in the shadow pass it is masked, with
  // alphaCutoff = transparency.shadowCutoff.
  bool blended = false;
  float alphaCutoff = 0.5f;
  bool unlit = false;     // the colour is O_d, no illumination (KHR_materials_unlit)
  bool additive = false;  // blended by the additive equation (PIPELINE.md, "Shading")
  bool castsShadow = true;  // drawn into the shadow maps
  // The ray tracer's recursive terms (PIPELINE.md, "Ray tracing"): k_r = reflectivity·O_s
  // of the reflected ray, k_t of the transmitted one, the index of refraction
  // n, and Beer's law's σ per channel inside the medium (0: no attenuation).
  float reflectivity = 0;
  float transmission = 0;
  float ior = 1.5f;
  glm::vec3 absorption{0.0f};
};

// The smallest derived exponent: (cos θ)^8 falls to half at θ = 23.6°, a
// lobe well inside the diffuse one (cos θ is half at 60°), so a rough
// material still has a highlight rather than a second, white diffuse term.
inline constexpr float kMinDerivedShininess = 8.0f;

// The one documented mapping from glTF metallic m and roughness r
// (renderer/PIPELINE.md, "Materials"):
//   α = r²,  n = clamp(2/α² - 2, 8, 1024)      (Blinn-Phong exponent matching
//                                               a Beckmann lobe of roughness α)
//   F0 = 0.04·(1 - m) + 0.9·m                  (dielectric vs. metal reflectance)
//   k_s = min(1, F0·(n + 8)/8)                 (energy-normalized peak of the lobe)
//   k_d = 1 - 0.6·m,  k_a = k_d                (punctual lights alone leave a metal
//                                               black outside its highlights)
//   O_s = (1 - m) + m·O_d                      (metals tint their highlights)
// Any of k_a, k_d, k_s, n set in `overrides` replaces the derived value.
// The ray tracer's: reflectivity = m·(1 - r), transmission and ior from
// KHR_materials_transmission and _ior, σ = -ln(attenuationColor)/attenuationDistance
// from KHR_materials_volume; the overrides replace the first three.
// Alpha: glTF's alphaMode, or `overrides.opacity` in the factor's place,
// which blends every material when below 1.
CourseMaterial courseMaterial(const Material& material, const MaterialOverrides& overrides, const TransparencySettings& transparency = {});

// The shadow pass and the triangle-id pass test α against alphaCutoff for a
// masked material, and the shadow pass for a blended one too.
inline bool masksShadow(const CourseMaterial& material) { return material.masked || material.blended; }

}  // namespace facet
