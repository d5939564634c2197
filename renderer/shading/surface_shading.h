#pragma once
// Pass 2's fragment stage at one point of a surface, whatever found the
// point: the rasterizer's varyings interpolated at a pixel
// (reference/reference_renderer.cpp), or a ray's hit (renderer/ray). The
// course's modes and shading=pbr, with the base colour, normal, bump and
// emissive textures of renderer/PIPELINE.md sections 5, 7 and 8; S from
// `shadows`, the light's shadow maps for a rasterizer
// (shadowFactorLanes(const ShadowMaps&, ...), lighting.h) or shadow rays
// for the ray tracer (an overload of shadowFactorLanes for its own type).
// The fast tiled renderer (lit_pass.cpp, phong_batch.cpp) computes the same
// in lanes and is held equal to the reference pixel for pixel.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/bump_mapping.h"
#include "shading/lighting.h"
#include "shading/normal_mapping.h"
#include "shading/physically_based.h"
#include "shading/procedural.h"
#include "shading/texture.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet {

// What the draw of one instance shades with, found once per draw.
struct SurfaceDraw {
  const Scene* scene = nullptr;
  const FrameInputs* frame = nullptr;
  const Mesh* mesh = nullptr;
  const CourseMaterial* material = nullptr;
  const Texture* texture = nullptr;      // the base colour texture, or none
  const Texture* normalMap = nullptr;    // Phong and pbr, where the material and the mesh have one
  const Texture* emissiveMap = nullptr;  // the course's modes: k_e·E per point
  bool bumpable = false;                 // the frame's bump map applies (Phong and pbr, a mesh with tangents)
  bool colored = false;                  // the mesh has COLOR_0
  // The coefficients the vertex and flat illuminations sum: k_e there is 0
  // where an emissive texture adds k_e·E at each point instead (PIPELINE.md, section 5).
  LaneMaterial<float> summed{};
};

inline SurfaceDraw surfaceDraw(const Scene& scene, const FrameInputs& frame, const FrameInstance& instance) {
  SurfaceDraw d;
  d.scene = &scene;
  d.frame = &frame;
  d.mesh = &scene.meshes[static_cast<std::size_t>(instance.mesh)];
  d.material = &frame.materials[static_cast<std::size_t>(instance.material)];
  d.texture = baseColorTextureOf(scene, frame, *d.material, *d.mesh);
  d.normalMap = interpolatesNormals(frame.shading) ? normalMapOf(scene, *d.material, *d.mesh) : nullptr;
  d.bumpable = interpolatesNormals(frame.shading) && frame.bump.map && !d.mesh->tangents.empty();
  d.colored = !d.mesh->colors.empty();
  d.emissiveMap = frame.shading != ShadingMode::Pbr ? emissiveMapOf(scene, *d.material, *d.mesh) : nullptr;
  d.summed = laneMaterial(*d.material, d.emissiveMap ? glm::vec3(0.0f) : d.material->emissive);
  return d;
}

// A point of the surface, as interpolated there.
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

// O_d = factor · COLOR_0 · texel, each factor only where the mesh has it; the
// texel is a procedural texture's grey where the frame has one.
inline glm::vec3 baseColorAt(const SurfaceDraw& d, const SurfacePoint& p) {
  const CourseMaterial& material = *d.material;
  glm::vec3 O = material.baseColor;
  if (d.colored) O = O * glm::vec3(p.color);
  if (d.frame->procedural != Procedural::None)
    O = O * proceduralGrey(d.frame->procedural, p.model, d.frame->proceduralScale);
  else if (d.texture)
    O = O * glm::vec3(sampleBaseColorTexture(*d.texture, material, p.st[material.baseColorSet], p.derivatives[material.baseColorSet]));
  return O;
}

// The unit normal Phong and pbr light the point with: the interpolated one
// bent by the normal texture, then by the bump map, normalized as the
// interpolated one is, and negated on a back face (two-sided lighting).
inline glm::vec3 shadingNormal(const SurfaceDraw& d, const SurfacePoint& p) {
  const CourseMaterial& material = *d.material;
  glm::vec3 normal = p.normal;
  const int normalSet = material.normalMap.set;
  if (d.normalMap) normal = normalMapped(*d.normalMap, material, normalize3(normal), p.tangent, p.st[normalSet], p.derivatives[normalSet]);
  if (d.bumpable) normal = bumped(*d.frame->bump.map, d.frame->bump.scale, normalize3(normal), p.tangent, p.st[0]);
  const glm::vec3 unit = normalize3(normal);
  return p.front ? unit : -unit;
}

// The linear colour of the point, before fog.
template <class Shadows>
glm::vec3 shadeSurface(const SurfaceDraw& d, const Shadows& shadows, const SurfacePoint& p) {
  const FrameInputs& frame = *d.frame;
  const CourseMaterial& material = *d.material;
  if (material.unlit) return baseColorAt(d, p);  // KHR_materials_unlit: O_d itself
  const auto emission = [&] {
    const int set = material.emissiveMap.set;
    return emissionAt(*d.emissiveMap, material, p.st[set], p.derivatives[set]);
  };
  if (interpolatesNormals(frame.shading)) {
    const glm::vec3 N = shadingNormal(d, p);
    if (frame.shading == ShadingMode::Pbr)
      return shadePhysicallyBased(frame, shadows, pbrSurfaceAt(*d.scene, material, *d.mesh, baseColorAt(d, p), p.st, p.derivatives), p.P, N,
                                  viewVector<float>(frame, p.P));
    const LaneMaterial<float> lit = laneMaterial(material, d.emissiveMap ? emission() : material.emissive);
    return shade(illuminate(frame, shadows, lit, p.P, N, viewVector<float>(frame, p.P)), baseColorAt(d, p));
  }
  Illumination I = p.lit;
  if (d.emissiveMap) I.specular = emission() + I.specular;
  return shade(I, baseColorAt(d, p));
}

}  // namespace facet
