#pragma once
// Pass 1's program on the CPU: a triangle's depth from a light's face, where
// its material casts a shadow; an alpha-masked or blended material's
// fragments only where its α passes (transparency.shadowCutoff for a
// blended one). Mirror: shaders/shadow_depth.vert and shadow_depth.frag.
#include <cstddef>

#include <glm/mat4x4.hpp>

#include "shading/alpha_mask.h"
#include "shading/draw_uniforms.h"
#include "shading/lit_varyings.h"
#include "shading/transform.h"

namespace facet {

struct ShadowDepthProgram {
  // What the alpha test reads, in the flat layout's places: the texture coordinates and COLOR_0.
  static constexpr VaryingLayout kLayout = varyingLayout(ShadingMode::Flat);
  static constexpr int kMaskVaryings = kLayout.color + 4;

  // gl_Position of mesh vertex i (world position `world`) in the light's
  // face, and with `masked` the varyings its alpha test reads.
  static glm::vec4 vertex(const glm::mat4& lightClipFromWorld, const Mesh& mesh, std::size_t i, glm::vec3 world, bool masked, float* v) {
    if (masked) putSurfaceVaryings(kLayout, mesh, i, kMaskVaryings, v);
    return transformPoint(lightClipFromWorld, world);
  }

  // Whether a fragment of a masked draw writes its depth (else it is discarded).
  static bool fragment(const DrawUniforms& d, const SurfacePoint& p) { return alphaKept(*d.material, alphaAt(d, p)); }
};

}  // namespace facet
