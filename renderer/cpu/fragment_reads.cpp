#include "cpu/fragment_reads.h"

#include "shading/normal_mapping.h"
#include "shading/texture.h"
#include "cpu/varyings.h"

namespace facet::cpu {

FragmentReads fragmentReads(ShadingMode mode, const Scene& scene, const FrameInputs& frame, const CourseMaterial& material, const Mesh& mesh) {
  const VaryingLayout layout = varyingLayout(mode);
  FragmentReads r;
  r.texture = baseColorTextureOf(scene, frame, material, mesh);
  r.normalMap = layout.tangent >= 0 ? normalMapOf(scene, material, mesh) : nullptr;
  r.emissiveMap = mode != ShadingMode::Pbr ? emissiveMapOf(scene, material, mesh) : nullptr;
  r.bumpable = layout.tangent >= 0 && frame.bump.map && !mesh.tangents.empty();
  r.colored = !mesh.colors.empty();
  r.used = frame.procedural != Procedural::None ? layout.count
           : r.colored                           ? layout.model
                                                 : (mode == ShadingMode::Flat && !r.texture && !r.emissiveMap ? 0 : layout.color);
  if (mode == ShadingMode::Phong && r.used == layout.color && !r.normalMap && !r.bumpable)
    r.used = r.texture || r.emissiveMap ? layout.tangent : layout.uv;
  return r;
}

}  // namespace facet::cpu
