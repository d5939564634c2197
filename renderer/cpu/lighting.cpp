#include "cpu/lighting.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "cpu/vertex_math.h"
#include "pipeline/light_frustum.h"

namespace facet::cpu {

float attenuation(glm::vec3 c, float d) {
  return std::min(1.0f, 1.0f / (c.x + c.y * d + c.z * d * d));
}

float specularTerm(glm::vec3 N, glm::vec3 L, glm::vec3 V, float shininess, SpecularModel model) {
  if (model == SpecularModel::Phong) {
    const glm::vec3 R = 2.0f * glm::dot(L, N) * N - L;
    return std::pow(std::max(glm::dot(R, V), 0.0f), shininess);
  }
  const glm::vec3 H = glm::normalize(L + V);
  return std::pow(std::max(glm::dot(N, H), 0.0f), shininess);
}

float shadowFactor(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, glm::vec3 P, glm::vec3 N, glm::vec3 L) {
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

Illumination illuminate(const FrameInputs& frame, const ShadowMaps& maps, const CourseMaterial& material, glm::vec3 P, glm::vec3 N,
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

glm::vec3 shade(const Illumination& illumination, glm::vec3 baseColor) {
  return baseColor * illumination.diffuse + illumination.specular;
}

glm::vec3 viewVector(const FrameInputs& frame, glm::vec3 P) {
  return frame.perspective ? glm::normalize(frame.eyePosition - P) : frame.towardEye;
}

glm::vec3 encodeSrgb(glm::vec3 linear) {
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) {
    const float c = linear[i] > 0.0f ? std::min(linear[i], 1.0f) : 0.0f;  // NaN -> 0; GLSL leaves clamp(NaN) undefined
    out[i] = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  }
  return out;
}

unsigned char quantize(float encoded) {
  const float c = encoded > 0.0f ? std::min(encoded, 1.0f) : 0.0f;  // NaN -> 0
  return static_cast<unsigned char>(std::floor(c * 255.0f + 0.5f));
}

}  // namespace facet::cpu
