#pragma once
// The alpha mask where the rasterizer meets it: α at a pixel of a triangle
// from its interpolated varyings (shading/alpha_mask.h's rule), evaluated
// where the z-buffer test is, before the fragment writes depth, so that what
// a mask cuts away hides nothing behind it.
#include "cpu/interpolation.h"
#include "shading/alpha_mask.h"
#include "shading/texture.h"
#include "shading/lit_varyings.h"
#include "pipeline/material_coefficients.h"

namespace facet::cpu {

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
