#pragma once
// Texture lookup: mipmap level of detail, the sampler's filters and wraps
// (renderer/PIPELINE.md, "Textures").
// Mirror: shaders/texture.glsl — same functions, same order.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "image/image.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet {

// The base colour texture a draw of `mesh` with `material` samples: none when
// the material has none, the mesh lacks the set it reads, or a procedural
// texture takes its place (PIPELINE.md, "Textures").
inline const Texture* baseColorTextureOf(const Scene& scene, const FrameInputs& frame, const CourseMaterial& material, const Mesh& mesh) {
  if (frame.procedural != Procedural::None || material.baseColorTexture < 0 || mesh.texcoordSet(material.baseColorSet).empty()) return nullptr;
  return &scene.textures[static_cast<std::size_t>(material.baseColorTexture)];
}

// The base colour texture's coordinates and their derivatives after the
// material's KHR_texture_transform (PIPELINE.md, "Textures"): st' by the
// 2×3 matrix, the derivatives by its linear part, each written out.
struct TransformedTexcoords {
  glm::vec2 st;
  glm::vec4 derivatives;  // (ds'/dx, dt'/dx, ds'/dy, dt'/dy)
};
inline TransformedTexcoords transformTexcoords(const CourseMaterial& m, glm::vec2 st, glm::vec4 d) {
  const glm::vec3 a = m.uvRow0, b = m.uvRow1;
  return {{(a.x * st.x + a.y * st.y) + a.z, (b.x * st.x + b.y * st.y) + b.z},
          {a.x * d.x + a.y * d.y, b.x * d.x + b.y * d.y, a.x * d.z + a.y * d.w, b.x * d.z + b.y * d.w}};
}

// REPEAT: i mod size in [0, size), with % only on non-negative operands.
inline int wrap(int i, int size) { return i >= 0 ? i % size : size - 1 - (-1 - i) % size; }

// The texel index i on an axis of `size` texels under `mode`.
int wrapIndex(int i, int size, Wrap mode);

// a + t·(b - a), written out on both sides (GLSL's mix may round as a·(1 - t) + b·t).
glm::vec4 lerp(glm::vec4 a, glm::vec4 b, float t);

// One level: NEAREST or LINEAR at texture coordinates st (t = 0 is the top
// of the glTF image; facet::Image stores the bottom row first): linear RGB
// (sRGB decoded, or the byte / 255 for data) and alpha (the byte / 255).
glm::vec4 sampleLevel(const Image& level, TexelEncoding encoding, bool linear, Wrap wrapS, Wrap wrapT, glm::vec2 st);

// sampleLevel over the size.x × size.y texels from `origin` of `image`, as if
// they were an image of their own (a face of an environment cube strip).
glm::vec4 sampleRegion(const Image& image, TexelEncoding encoding, glm::ivec2 origin, glm::ivec2 size, bool linear, Wrap wrapS, Wrap wrapT,
                       glm::vec2 st);

// ρ² of PIPELINE.md, "Textures", from derivatives (ds/dx, dt/dx, ds/dy, dt/dy) and level 0's size.
float footprintSquared(glm::vec4 derivatives, int width, int height);

// The texture through `sampler` at st, derivatives as dFdx(st), dFdy(st)
// (Interpolation::quadDerivatives): linear RGB and alpha.
glm::vec4 sampleTexture(const Texture& texture, const Sampler& sampler, glm::vec2 st, glm::vec4 derivatives);

// Whether a draw of `mesh` reads `map`: the material has it and the mesh has the set it reads.
inline bool readsMap(const MaterialMap& map, const Mesh& mesh) { return map.texture >= 0 && !mesh.texcoordSet(map.set).empty(); }

// The emissive texture a draw of `mesh` with `material` reads, or null (PIPELINE.md, "Materials").
inline const Texture* emissiveMapOf(const Scene& scene, const CourseMaterial& material, const Mesh& mesh) {
  return readsMap(material.emissiveMap, mesh) ? &scene.textures[static_cast<std::size_t>(material.emissiveMap.texture)] : nullptr;
}

// k_e·E: the emissive texture's RGB at st (its set's) with derivatives d, times k_e. Every shading mode's.
inline glm::vec3 emissionAt(const Texture& map, const CourseMaterial& m, glm::vec2 st, glm::vec4 d) {
  return m.emissive * glm::vec3(sampleTexture(map, m.emissiveMap.sampler, st, d));
}

// A material's base colour texture at the fragment's st (of its set) and its derivatives: transformed, then sampled.
inline glm::vec4 sampleBaseColorTexture(const Texture& texture, const CourseMaterial& m, glm::vec2 st, glm::vec4 derivatives) {
  const TransformedTexcoords t = transformTexcoords(m, st, derivatives);
  return sampleTexture(texture, m.baseColorSampler, t.st, t.derivatives);
}

}  // namespace facet
