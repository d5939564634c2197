#pragma once
// What the fragment stage reads of an instance's triangles, besides P and N
// or the illumination: its maps, and `used`, the prefix of the varying
// layout (varyings.h) it sets up. Every reader of a triangle's varyings (the
// shading loop, the blend's α, the alpha mask in either hidden-surface
// method) sets up that prefix at most, and the lit pass's vertex stage
// packs the most that any instance reads: no plane is set up past what was
// packed.
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet::cpu {

struct FragmentReads {
  const Texture* texture = nullptr;
  const Texture* normalMap = nullptr;    // Phong and pbr
  const Texture* emissiveMap = nullptr;  // the course's modes (pbr reads it in pbrSurfaceAt)
  bool bumpable = false;                 // Phong and pbr: the frame has a bump map and the mesh tangents
  bool colored = false;
  // Everything with a procedural pattern; up to the model position with
  // vertex colours; none for flat without maps; Phong: P and N, the texture
  // coordinates only with a map, the tangent only with a normal or bump map.
  int used = 0;
};

FragmentReads fragmentReads(ShadingMode mode, const Scene& scene, const FrameInputs& frame, const CourseMaterial& material, const Mesh& mesh);

}  // namespace facet::cpu
