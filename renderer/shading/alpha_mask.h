#pragma once
// alphaMode MASK (renderer/PIPELINE.md, "Textures"): a fragment of a masked
// material is kept when α = (factor.a · COLOR_0.a) · texel.a, each where
// present, is at least the cutoff; a NaN α discards.
// Mirror: alphaKept in shaders/draw_uniforms.glsl.
#include <glm/vec4.hpp>

#include "pipeline/material_coefficients.h"

namespace facet {

// α from the texel (the base colour texture's sample, or null without one)
// and the interpolated COLOR_0 alpha (null without one).
inline float fragmentAlpha(const CourseMaterial& material, const float* vertexAlpha, const glm::vec4* texel) {
  float alpha = material.baseAlpha;
  if (vertexAlpha) alpha = alpha * *vertexAlpha;
  if (texel) alpha = alpha * texel->a;
  return alpha;
}

inline bool alphaKept(const CourseMaterial& material, float alpha) { return alpha >= material.alphaCutoff; }

}  // namespace facet
