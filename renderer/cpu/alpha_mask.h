#pragma once
// alphaMode MASK (renderer/PIPELINE.md, section 8): a fragment of a masked
// material is kept when α = (factor.a · COLOR_0.a) · texel.a, each where
// present, is at least the cutoff; a NaN α discards. Evaluated where the
// z-buffer test is, before the fragment writes depth, so that what a mask
// cuts away hides nothing behind it.
// Mirror: alphaKept in shaders/draw_uniforms.glsl.
#include "cpu/interpolation.h"
#include "cpu/texture_sampling.h"
#include "cpu/varyings.h"
#include "pipeline/material_coefficients.h"

namespace facet::cpu {

// α from the texel (the base colour texture's sample, or null without one)
// and the interpolated COLOR_0 alpha (null without one).
inline float fragmentAlpha(const CourseMaterial& material, const float* vertexAlpha, const glm::vec4* texel) {
  float alpha = material.baseAlpha;
  if (vertexAlpha) alpha = alpha * *vertexAlpha;
  if (texel) alpha = alpha * texel->a;
  return alpha;
}

inline bool alphaKept(const CourseMaterial& material, float alpha) { return alpha >= material.alphaCutoff; }

// α at pixel (px, py) of a triangle whose planes `in` has set up up to the
// layout's vertex colour (`texture`: the base colour texture, null when the
// material or the mesh has none).
inline float fragmentAlphaAt(const CourseMaterial& material, const Texture* texture, bool colored, VaryingLayout layout, const Interpolation& in,
                             int px, int py) {
  glm::vec4 texel{1.0f};
  if (texture) {
    const int uv = layout.texcoord(material.baseColorSet);
    const glm::vec2 st{in.varyingAt(uv, px, py), in.varyingAt(uv + 1, px, py)};
    texel = sampleBaseColorTexture(*texture, material, st, in.quadDerivatives(uv, px, py));
  }
  const float vertexAlpha = colored ? in.varyingAt(layout.color + 3, px, py) : 1.0f;
  return fragmentAlpha(material, colored ? &vertexAlpha : nullptr, texture ? &texel : nullptr);
}

// The mask's test there.
inline bool keepsFragment(const CourseMaterial& material, const Texture* texture, bool colored, VaryingLayout layout, const Interpolation& in,
                          int px, int py) {
  return alphaKept(material, fragmentAlphaAt(material, texture, colored, layout, in, px, py));
}

}  // namespace facet::cpu
