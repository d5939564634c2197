#pragma once
// What the lit pass interpolates per shading mode, after a window vertex's
// x, y, z, 1/w: the fast renderer's packed vertices and the reference's
// clip vertices lay them out alike.
//   Phong and pbr: world position 0-2, normal 3-5, TEXCOORD_0 6-7, TEXCOORD_1 8-9,
//            world tangent and its w 10-13, vertex colour 14-17, model position 18-20
//   Gouraud: front diffuse 0-2, front specular 3-5, back diffuse 6-8,
//            back specular 9-11, TEXCOORD_0 12-13, TEXCOORD_1 14-15, vertex colour 16-19,
//            model position 20-22
//   flat:    TEXCOORD_0 0-1, TEXCOORD_1 2-3, vertex colour 4-7, model position 8-10
//            (the illumination is per triangle)
// The vertex colour is RGBA: its alpha is the alpha mask's. The model-space
// position (procedural textures) comes last and is packed only in frames
// that use it; the vertex colour comes before it so that a mesh without one
// sets up only the planes before that.
#include "cpu/clipper.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet::cpu {

struct VaryingLayout {
  int count = 0;  // varyings in use
  int uv = 0;     // TEXCOORD_0's s, then t, then TEXCOORD_1's s and t
  int color = 0;  // the vertex colour's red (COLOR_0: R, G, B, A)
  int model = 0;  // the model-space position's x (procedural textures); model = color + 4, count = model + 3
  int tangent = -1;  // the world tangent's x, then y, z, w (normal textures; Phong and pbr only), -1 = none

  // The varyings a frame packs: all of them with a procedural texture, else those before the model position.
  int packed(Procedural procedural) const { return procedural == Procedural::None ? model : count; }
  // The s of texture coordinate set `set` (a material's reference: TEXCOORD_1 for 1, else TEXCOORD_0).
  constexpr int texcoord(int set) const { return uv + (set == 1 ? 2 : 0); }
};

// Both texture coordinate sets of a mesh's vertex `local` into varyings[uv .. uv + 3], (0, 0) for a set it lacks.
inline void putTexcoords(float* varyings, int uv, const Mesh& mesh, std::size_t local) {
  for (int set = 0; set < 2; ++set) {
    const std::vector<glm::vec2>& st = mesh.texcoordSet(set);
    const glm::vec2 value = st.empty() ? glm::vec2(0.0f) : st[local];
    varyings[uv + 2 * set] = value.x;
    varyings[uv + 2 * set + 1] = value.y;
  }
}

constexpr VaryingLayout varyingLayout(ShadingMode mode) {
  switch (mode) {
    case ShadingMode::Phong:
    case ShadingMode::Pbr: return {21, 6, 14, 18, 10};
    case ShadingMode::Gouraud: return {23, 12, 16, 20};
    default: return {11, 0, 4, 8};
  }
}
static_assert(varyingLayout(ShadingMode::Gouraud).count <= kMaxVaryings && varyingLayout(ShadingMode::Phong).count <= kMaxVaryings &&
              varyingLayout(ShadingMode::Flat).count <= kMaxVaryings);

}  // namespace facet::cpu
