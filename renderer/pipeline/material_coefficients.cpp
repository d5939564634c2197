#include "pipeline/material_coefficients.h"

#include <algorithm>
#include <cmath>

namespace facet {

CourseMaterial courseMaterial(const Material& material, const MaterialOverrides& overrides, const TransparencySettings& transparency) {
  const float m = std::clamp(material.metallic, 0.0f, 1.0f);
  const float r = std::clamp(material.roughness, 0.0f, 1.0f);
  const float alpha = r * r;
  const float n = alpha > 0.0f ? std::clamp(2.0f / (alpha * alpha) - 2.0f, kMinDerivedShininess, 1024.0f) : 1024.0f;
  const float f0 = 0.04f * (1.0f - m) + 0.9f * m;
  CourseMaterial out;
  out.baseColor = glm::vec3(material.baseColor);
  out.baseAlpha = overrides.opacity.value_or(material.baseColor.a);
  // KHR_texture_transform: T·R·S, turned as Khronos' TextureTransformTest checks (PIPELINE.md, "Textures"), in double, rounded once.
  const TextureTransform& t = material.baseColorTransform;
  const double c = std::cos(static_cast<double>(t.rotation)), s = std::sin(static_cast<double>(t.rotation));
  out.uvRow0 = glm::vec3(static_cast<float>(c * t.scale.x), static_cast<float>(s * t.scale.y), t.offset.x);
  out.uvRow1 = glm::vec3(static_cast<float>(-s * t.scale.x), static_cast<float>(c * t.scale.y), t.offset.y);
  out.blended = material.alphaMode == AlphaMode::Blend || (overrides.opacity && *overrides.opacity < 1.0f);
  out.masked = material.alphaMode == AlphaMode::Mask && !out.blended;
  out.alphaCutoff = out.blended ? transparency.shadowCutoff : material.alphaCutoff;
  out.unlit = material.unlit;
  out.additive = out.blended && material.additive;
  out.castsShadow = material.castsShadow;
  out.baseColorTexture = material.baseColorTexture;
  const TexcoordSets& sets = material.texcoordSets;
  out.baseColorSet = sets.baseColor;
  out.metallicRoughnessMap.set = sets.metallicRoughness;
  out.occlusionMap.set = sets.occlusion;
  out.emissiveMap.set = sets.emissive;
  out.normalMap.set = sets.normal;
  out.emissive = material.emissive;
  out.kd = overrides.kd.value_or(1.0f - 0.6f * m);
  out.ka = overrides.ka.value_or(1.0f - 0.6f * m);
  out.ks = overrides.ks.value_or(std::min(1.0f, f0 * (n + 8.0f) / 8.0f));
  out.shininess = overrides.shininess.value_or(n);
  out.metallic = m;
  out.roughness = r;
  out.metallicRoughnessMap.texture = material.metallicRoughnessTexture;
  out.occlusionMap.texture = material.occlusionTexture;
  out.emissiveMap.texture = material.emissiveTexture;
  out.occlusionStrength = material.occlusionStrength;
  out.normalMap.texture = material.normalTexture;
  out.normalScale = material.normalScale;
  out.doubleSided = material.doubleSided;
  out.reflectivity = overrides.reflectivity.value_or(m * (1.0f - r));
  out.transmission = overrides.transmission.value_or(std::clamp(material.transmission, 0.0f, 1.0f));
  out.ior = overrides.ior.value_or(material.ior);
  // Beer's law: what is left after attenuationDistance is attenuationColor, so σ = -ln(c)/d per channel
  // (a channel of c = 0 absorbs everything: σ infinite).
  if (std::isfinite(material.attenuationDistance) && material.attenuationDistance > 0.0f)
    for (int k = 0; k < 3; ++k) out.absorption[k] = -std::log(std::clamp(material.attenuationColor[k], 0.0f, 1.0f)) / material.attenuationDistance;
  return out;
}

}  // namespace facet
