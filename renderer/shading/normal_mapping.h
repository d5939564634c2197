#pragma once
// glTF normal textures (renderer/PIPELINE.md, "Normal textures"):
// the tangent-space normal of the texture turned into world space by the
// pixel's tangent frame. Mirror: shaders/normal_mapping.glsl.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/shading_math.h"
#include "shading/texture.h"

namespace facet {

// The normal texture a draw of `mesh` with `material` reads in Phong and pbr: none without one or without tangents.
inline const Texture* normalMapOf(const Scene& scene, const CourseMaterial& material, const Mesh& mesh) {
  if (material.normalMap.texture < 0 || mesh.tangents.empty() || mesh.texcoordSet(material.normalMap.set).empty()) return nullptr;
  return &scene.textures[static_cast<std::size_t>(material.normalMap.texture)];
}

// The pixel's unit tangent frame from the unit normal N and the interpolated tangent t and its w:
// T = normalize3(t - N·(N·t)), B = (w < 0 ? -1 : 1)·(N × T). Normal textures and bump mapping share it.
struct TangentFrame {
  glm::vec3 T, B;
};
inline TangentFrame tangentFrame(glm::vec3 N, glm::vec4 tangent) {
  const glm::vec3 t(tangent);
  const glm::vec3 T = normalize3(t - N * dot3(N, t));
  return {T, (tangent.w < 0.0f ? -1.0f : 1.0f) * cross3(N, T)};
}

// N' before it is normalized: n = (2·texel - 1) with x, y times the scale,
// T = normalize3(t - N·(N·t)), B = ±(N × T) by the tangent's w, N' = (T·n.x + B·n.y) + N·n.z.
// N is the unit interpolated normal, `tangent` the interpolated world tangent and w, st and d as the base colour's.
inline glm::vec3 normalMapped(const Texture& map, const CourseMaterial& material, glm::vec3 N, glm::vec4 tangent, glm::vec2 st, glm::vec4 d) {
  const glm::vec4 texel = sampleTexture(map, material.normalMap.sampler, st, d);
  const float x = (2.0f * texel.r - 1.0f) * material.normalScale, y = (2.0f * texel.g - 1.0f) * material.normalScale;
  const float z = 2.0f * texel.b - 1.0f;
  const TangentFrame f = tangentFrame(N, tangent);
  return (f.T * x + f.B * y) + N * z;
}

}  // namespace facet
