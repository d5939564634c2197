#pragma once
// What the draw of one instance reads, found once per draw: its mesh and
// material, the maps it samples, and how much of its varyings any stage
// reads (renderer/PIPELINE.md, "Materials", "Shading" and "Textures"); and the functions of
// the draw's base colour and emission at a point.
// Mirror: shaders/draw_uniforms.glsl (the uniforms and specialization
// macros of a draw: FACET_TEXTURED, FACET_COLORED, FACET_EMISSIVE_MAP,
// FACET_NORMAL_MAP, FACET_BUMP_MAP, FACET_PROCEDURAL).
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "pipeline/frame_inputs.h"
#include "scene/scene.h"
#include "shading/lighting.h"
#include "shading/lit_varyings.h"

namespace facet {

struct DrawUniforms {
  const Scene* scene = nullptr;
  const FrameInputs* frame = nullptr;
  const Mesh* mesh = nullptr;
  const CourseMaterial* material = nullptr;
  const Texture* texture = nullptr;      // FACET_TEXTURED: the base colour texture, or none
  const Texture* normalMap = nullptr;    // FACET_NORMAL_MAP: Phong and pbr, where the material and the mesh have one
  const Texture* emissiveMap = nullptr;  // FACET_EMISSIVE_MAP: the course's modes, k_e·E per point (pbr reads it in pbrSurfaceAt)
  bool bumpable = false;                 // FACET_BUMP_MAP: the frame's bump map applies (Phong and pbr, a mesh with tangents)
  bool colored = false;                  // FACET_COLORED: the mesh has COLOR_0
  bool procedural = false;               // FACET_PROCEDURAL: a pattern in place of the base colour texture
  // summedMaterial(): the coefficients the vertex and flat illuminations sum,
  // k_e there 0 where an emissive texture adds k_e·E at each point instead
  // (PIPELINE.md, "Materials").
  LaneMaterial<float> summed{};
  // The prefix of the mode's varying layout any stage of the draw reads (its
  // fragments, their α, the alpha mask): a rasterizer sets up that much.
  // Everything with a procedural pattern; up to the model position with
  // vertex colours; none for flat without maps; Phong: P and N, the texture
  // coordinates only with a map, the tangent only with a normal or bump map.
  int used = 0;
  // Which texture coordinate sets a map of the draw samples: the fragment's
  // derivatives are needed for those only.
  bool samplesSet[2] = {false, false};
};

// The uniforms of a draw of `mesh` with `material` in `frame` (frame.shading's mode).
DrawUniforms drawUniforms(const Scene& scene, const FrameInputs& frame, const CourseMaterial& material, const Mesh& mesh);
inline DrawUniforms drawUniforms(const Scene& scene, const FrameInputs& frame, const FrameInstance& instance) {
  return drawUniforms(scene, frame, frame.materials[static_cast<std::size_t>(instance.material)],
                      scene.meshes[static_cast<std::size_t>(instance.mesh)]);
}

// O_d = factor · COLOR_0 · texel, each factor only where the draw has it; the
// texel is a procedural texture's grey where the frame has one.
glm::vec3 baseColorAt(const DrawUniforms& d, const SurfacePoint& p);

// α = (factor.a · COLOR_0.a) · texel.a at the point, each where the draw has
// it: what the alpha mask tests and a blended fragment is blended with.
float alphaAt(const DrawUniforms& d, const SurfacePoint& p);

// k_e·E at the point: the emissive texture's RGB at its set, times k_e (a draw with an emissive map).
glm::vec3 emissionAt(const DrawUniforms& d, const SurfacePoint& p);

}  // namespace facet
