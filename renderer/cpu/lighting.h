#pragma once
// The course's illumination equation on the CPU.
// Mirror: shaders/lighting.glsl — the same functions, in the same order, with
// the same names and arguments. Change one, change the other.
//
//   I = k_e + k_a·I_a·O_d + Σ_lights S·f_att·(k_d·I_p·max(N·L, 0)·O_d + k_s·I_p·spec)
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "cpu/shadow_maps.h"
#include "cpu/vertex_math.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/light_frustum.h"

namespace facet::cpu {

// f_att = min(1, 1/(c1 + c2·d + c3·d²))
float attenuation(glm::vec3 c, float d);

// spec = max(R·V, 0)^n with R = 2(L·N)N - L (Phong), or max(N·H, 0)^n with
// H = normalize(L + V) (Blinn-Phong). The caller skips it where N·L ≤ 0.
float specularTerm(glm::vec3 N, glm::vec3 L, glm::vec3 V, float shininess, SpecularModel model);

// S of one light at world point P: PCF over (2r+1)² texels of the light's
// map, a texel in shadow when z - bias > depth, bias = max(b_slope·(1 - N·L), b_min).
// Outside the map (or beyond its far plane) counts as lit.
float shadowFactor(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, glm::vec3 P, glm::vec3 N, glm::vec3 L);

// I split in the part O_d multiplies and the rest, so that a textured O_d can
// be applied per pixel when lighting is per vertex (Gouraud) or per triangle (flat):
//   I = O_d·diffuse + specular
//   diffuse  = k_a·I_a + Σ S·f_att·k_d·I_p·max(N·L, 0)
//   specular = k_e + Σ S·f_att·k_s·I_p·spec
struct Illumination {
  glm::vec3 diffuse{0.0f};
  glm::vec3 specular{0.0f};
};

// Illumination at world point P with unit normal N and unit view vector V.
Illumination illuminate(const FrameInputs& frame, const ShadowMaps& maps, const CourseMaterial& material, glm::vec3 P, glm::vec3 N,
                        glm::vec3 V);

// I = O_d·diffuse + specular (linear, unclamped).
glm::vec3 shade(const Illumination& illumination, glm::vec3 baseColor);

// V at P: toward the eye (perspective) or the constant -k (parallel).
glm::vec3 viewVector(const FrameInputs& frame, glm::vec3 P);

// Clamp to [0,1], then IEC 61966-2-1: 12.92·c below 0.0031308, else 1.055·c^(1/2.4) - 0.055.
glm::vec3 encodeSrgb(glm::vec3 linear);

// sRGB-encoded [0,1] to 8 bits, rounding to nearest.
unsigned char quantize(float encoded);

// [SECTION] Definitions, inline so that the fragment stage compiles them into its loop.

inline float attenuation(glm::vec3 c, float d) {
  return std::min(1.0f, 1.0f / (c.x + c.y * d + c.z * d * d));
}

inline float specularTerm(glm::vec3 N, glm::vec3 L, glm::vec3 V, float shininess, SpecularModel model) {
  if (model == SpecularModel::Phong) {
    const glm::vec3 R = 2.0f * glm::dot(L, N) * N - L;
    return std::pow(std::max(glm::dot(R, V), 0.0f), shininess);
  }
  const glm::vec3 H = glm::normalize(L + V);
  return std::pow(std::max(glm::dot(N, H), 0.0f), shininess);
}

inline float shadowFactor(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, glm::vec3 P, glm::vec3 N, glm::vec3 L) {
  if (!light.hasShadowMap) return 1.0f;
  const int face = light.light.kind == LightKind::Point ? cubeFace(P - light.light.position) : 0;
  const glm::vec4 s = transformPoint(light.shadowFromWorld[static_cast<std::size_t>(face)], P);
  if (!(s.w > 0.0f)) return 1.0f;
  glm::vec3 uvz = glm::vec3(s) / s.w;
  if (!(uvz.z <= 1.0f) || std::isnan(uvz.x) || std::isnan(uvz.y)) return 1.0f;
  // Far outside the map every texel is outside too; the clamp keeps the texel
  // index an int without changing which texels a point inside reads.
  uvz.x = std::clamp(uvz.x, -1.0f, 2.0f);
  uvz.y = std::clamp(uvz.y, -1.0f, 2.0f);
  const float bias = std::max(shadows.biasSlope * (1.0f - glm::dot(N, L)), shadows.biasMin);
  const int size = maps.size, r = shadows.pcfRadius;
  const int tx = static_cast<int>(std::floor(uvz.x * static_cast<float>(size)));
  const int ty = static_cast<int>(std::floor(uvz.y * static_cast<float>(size)));
  const int layer = light.shadowLayer + face;
  int lit = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const int x = tx + dx, y = ty + dy;
      if (x < 0 || y < 0 || x >= size || y >= size) ++lit;
      else if (!(uvz.z - bias > maps.texelFetch(layer, x, y))) ++lit;
    }
  return static_cast<float>(lit) / static_cast<float>((2 * r + 1) * (2 * r + 1));
}

inline Illumination illuminate(const FrameInputs& frame, const ShadowMaps& maps, const CourseMaterial& material, glm::vec3 P, glm::vec3 N,
                        glm::vec3 V) {
  Illumination I;
  I.diffuse = glm::vec3(material.ka * frame.ambient);
  I.specular = material.emissive;
  for (const FrameLight& fl : frame.lights) {
    const Light& light = fl.light;
    glm::vec3 L;
    float fAtt = 1.0f;
    if (light.kind == LightKind::Directional) {
      L = -light.direction;
    } else {
      const glm::vec3 toLight = light.position - P;
      const float d = glm::length(toLight);
      L = toLight / d;
      fAtt = attenuation(light.attenuation, d);
    }
    if (light.kind == LightKind::Spot && !(glm::dot(-L, light.direction) > fl.cosCutoff)) continue;
    const float NdotL = glm::dot(N, L);
    if (!(NdotL > 0.0f)) continue;  // no diffuse and no specular where N·L ≤ 0
    const glm::vec3 Ip = light.color * light.intensity;
    const float S = shadowFactor(maps, fl, frame.shadows, P, N, L);
    I.diffuse += S * fAtt * (material.kd * NdotL * Ip);
    I.specular += S * fAtt * (material.ks * specularTerm(N, L, V, material.shininess, frame.specular) * Ip);
  }
  return I;
}

inline glm::vec3 shade(const Illumination& illumination, glm::vec3 baseColor) {
  return baseColor * illumination.diffuse + illumination.specular;
}

inline glm::vec3 viewVector(const FrameInputs& frame, glm::vec3 P) {
  return frame.perspective ? glm::normalize(frame.eyePosition - P) : frame.towardEye;
}

}  // namespace facet::cpu
