#pragma once
// What the lit pass interpolates per shading mode, after a window vertex's
// x, y, z, 1/w: the fast renderer's packed vertices and the reference's
// clip vertices lay them out alike.
//   Phong and pbr: world position 0-2, normal 3-5, texture coordinates 6-7,
//            world tangent and its w 8-11, vertex colour 12-15, model position 16-18
//   Gouraud: front diffuse 0-2, front specular 3-5, back diffuse 6-8,
//            back specular 9-11, texture coordinates 12-13, vertex colour 14-17,
//            model position 18-20
//   flat:    texture coordinates 0-1, vertex colour 2-5, model position 6-8
//            (the illumination is per triangle)
// The vertex colour is RGBA: its alpha is the alpha mask's. The model-space
// position (procedural textures) comes last and is packed only in frames
// that use it; the vertex colour comes before it so that a mesh without one
// sets up only the planes before that.
#include "cpu/clipper.h"
#include "settings/render_settings.h"

namespace facet::cpu {

struct VaryingLayout {
  int count = 0;  // varyings in use
  int uv = 0;     // the first texture coordinate
  int color = 0;  // the vertex colour's red (COLOR_0: R, G, B, A)
  int model = 0;  // the model-space position's x (procedural textures); model = color + 4, count = model + 3
  int tangent = -1;  // the world tangent's x, then y, z, w (normal textures; Phong and pbr only), -1 = none

  // The varyings a frame packs: all of them with a procedural texture, else those before the model position.
  int packed(Procedural procedural) const { return procedural == Procedural::None ? model : count; }
};

constexpr VaryingLayout varyingLayout(ShadingMode mode) {
  switch (mode) {
    case ShadingMode::Phong:
    case ShadingMode::Pbr: return {19, 6, 12, 16, 8};
    case ShadingMode::Gouraud: return {21, 12, 14, 18};
    default: return {9, 0, 2, 6};
  }
}
static_assert(varyingLayout(ShadingMode::Gouraud).count <= kMaxVaryings && varyingLayout(ShadingMode::Phong).count <= kMaxVaryings &&
              varyingLayout(ShadingMode::Flat).count <= kMaxVaryings);

}  // namespace facet::cpu
