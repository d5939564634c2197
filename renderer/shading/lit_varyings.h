#pragma once
// What the lit programs' vertex stage hands their fragment stage (the `out`
// variables of shaders/lit_*.vert, the `in` ones of lit_*.frag), in two
// forms: packed floats, which a rasterizer interpolates across a triangle,
// and SurfacePoint, the point of a surface the fragment program shades,
// whatever found it (a rasterizer's pixel, a ray's hit).
//
// Packed after a window vertex's x, y, z, 1/w, per shading mode:
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
#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/scene.h"
#include "shading/lighting.h"
#include "vocabulary/enums.h"

namespace facet {

inline constexpr int kMaxVaryings = 23;  // the most varyingLayout uses (Gouraud's)

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

// Both texture coordinate sets of a mesh's vertex `local` into varyings[uv .. uv + 3], (0, 0) for a set it lacks.
inline void putTexcoords(float* varyings, int uv, const Mesh& mesh, std::size_t local) {
  for (int set = 0; set < 2; ++set) {
    const std::vector<glm::vec2>& st = mesh.texcoordSet(set);
    const glm::vec2 value = st.empty() ? glm::vec2(0.0f) : st[local];
    varyings[uv + 2 * set] = value.x;
    varyings[uv + 2 * set + 1] = value.y;
  }
}

// A point of a surface, as the fragment program reads it.
struct SurfacePoint {
  glm::vec3 P{0.0f};                   // world position (Phong, pbr)
  glm::vec3 normal{0.0f};              // world normal as interpolated, not yet normalized (Phong, pbr)
  glm::vec4 tangent{0.0f, 0.0f, 0.0f, 1.0f};  // world tangent, w the bitangent's side (normal and bump maps)
  glm::vec2 st[2]{};                   // TEXCOORD_0 and TEXCOORD_1
  glm::vec4 derivatives[2]{};          // (ds/dx, dt/dx, ds/dy, dt/dy) of each set in pixels: the textures' level of detail
  glm::vec4 color{1.0f};               // COLOR_0
  glm::vec3 model{0.0f};               // model-space position (procedural textures)
  bool front = true;                   // the side seen: a back face is lit with -N
  Illumination lit{};                  // Gouraud: the side's interpolated illumination; flat: the triangle's
};

// The point packed varyings `v` describe, interpolated at a pixel of a
// triangle seen from `front`: the first `used` of the frame's layout (the
// rest keep SurfacePoint's defaults), flat's illumination from `flat` (the
// triangle's, front then back). Texture coordinate derivatives are the
// caller's: only it knows how the varyings vary.
inline SurfacePoint surfacePointOf(ShadingMode mode, const float* v, int used, bool front, const Illumination* flat) {
  const VaryingLayout layout = varyingLayout(mode);
  SurfacePoint p;
  p.front = front;
  if (used >= layout.uv + 4)
    for (int set = 0; set < 2; ++set) p.st[set] = glm::vec2(v[layout.texcoord(set)], v[layout.texcoord(set) + 1]);
  if (used >= layout.color + 4) p.color = glm::vec4(v[layout.color], v[layout.color + 1], v[layout.color + 2], v[layout.color + 3]);
  if (used >= layout.model + 3) p.model = glm::vec3(v[layout.model], v[layout.model + 1], v[layout.model + 2]);
  if (interpolatesNormals(mode)) {
    p.P = glm::vec3(v[0], v[1], v[2]);
    p.normal = glm::vec3(v[3], v[4], v[5]);
    if (used >= layout.tangent + 4) p.tangent = glm::vec4(v[layout.tangent], v[layout.tangent + 1], v[layout.tangent + 2], v[layout.tangent + 3]);
  } else if (mode == ShadingMode::Gouraud) {
    const int side = front ? 0 : 6;
    p.lit = Illumination{{v[side], v[side + 1], v[side + 2]}, {v[side + 3], v[side + 4], v[side + 5]}};
  } else {
    p.lit = front ? flat[0] : flat[1];
  }
  return p;
}

}  // namespace facet
