#include "shading/draw_uniforms.h"

#include "shading/alpha_mask.h"
#include "shading/normal_mapping.h"
#include "shading/procedural.h"
#include "shading/texture.h"

namespace facet {

DrawUniforms drawUniforms(const Scene& scene, const FrameInputs& frame, const CourseMaterial& material, const Mesh& mesh) {
  const ShadingMode mode = frame.shading;
  const VaryingLayout layout = varyingLayout(mode);
  DrawUniforms d;
  d.scene = &scene;
  d.frame = &frame;
  d.mesh = &mesh;
  d.material = &material;
  d.texture = baseColorTextureOf(scene, frame, material, mesh);
  d.normalMap = interpolatesNormals(mode) ? normalMapOf(scene, material, mesh) : nullptr;
  d.emissiveMap = mode != ShadingMode::Pbr ? emissiveMapOf(scene, material, mesh) : nullptr;
  d.bumpable = interpolatesNormals(mode) && frame.bump.map && !mesh.tangents.empty();
  d.colored = !mesh.colors.empty();
  d.procedural = frame.procedural != Procedural::None;
  d.summed = laneMaterial(material, d.emissiveMap ? glm::vec3(0.0f) : material.emissive);
  d.used = d.procedural ? layout.count
           : d.colored  ? layout.model
                        : (mode == ShadingMode::Flat && !d.texture && !d.emissiveMap ? 0 : layout.color);
  if (mode == ShadingMode::Phong && d.used == layout.color && !d.normalMap && !d.bumpable)
    d.used = d.texture || d.emissiveMap ? layout.tangent : layout.uv;
  const auto samples = [&](bool read, int set) {
    if (read) d.samplesSet[set == 1 ? 1 : 0] = true;
  };
  samples(d.texture != nullptr, material.baseColorSet);
  samples(d.normalMap != nullptr, material.normalMap.set);
  samples(d.emissiveMap != nullptr, material.emissiveMap.set);
  if (mode == ShadingMode::Pbr)  // pbrSurfaceAt samples every map the mesh has the set of
    for (const MaterialMap* map : {&material.metallicRoughnessMap, &material.occlusionMap, &material.emissiveMap})
      samples(readsMap(*map, mesh), map->set);
  return d;
}

glm::vec3 baseColorAt(const DrawUniforms& d, const SurfacePoint& p) {
  const CourseMaterial& material = *d.material;
  glm::vec3 O = material.baseColor;
  if (d.colored) O = O * glm::vec3(p.color);
  if (d.procedural)
    O = O * proceduralGrey(d.frame->procedural, p.model, d.frame->proceduralScale);
  else if (d.texture)
    O = O * glm::vec3(sampleBaseColorTexture(*d.texture, material, p.st[material.baseColorSet], p.derivatives[material.baseColorSet]));
  return O;
}

float alphaAt(const DrawUniforms& d, const SurfacePoint& p) {
  const CourseMaterial& material = *d.material;
  glm::vec4 texel{1.0f};
  if (d.texture) texel = sampleBaseColorTexture(*d.texture, material, p.st[material.baseColorSet], p.derivatives[material.baseColorSet]);
  const float vertexAlpha = p.color.a;
  return fragmentAlpha(material, d.colored ? &vertexAlpha : nullptr, d.texture ? &texel : nullptr);
}

glm::vec3 emissionAt(const DrawUniforms& d, const SurfacePoint& p) {
  const int set = d.material->emissiveMap.set;
  return emissionAt(*d.emissiveMap, *d.material, p.st[set], p.derivatives[set]);
}

}  // namespace facet
