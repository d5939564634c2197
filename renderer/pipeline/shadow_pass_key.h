#pragma once
// What pass 1 of the 2-pass shadow algorithm reads of a frame
// (renderer/PIPELINE.md, "Materials"): the scene's content, the maps' size and
// layers, each shadowed light's frusta, each instance's mesh, TM and
// material, and of the material what decides which fragments cast a shadow
// (castsShadow, the alpha mask and the base colour texture it reads). The
// camera is not in it: two frames with equal keys draw the same maps, so a
// renderer keeps the maps it drew for the first, and an orbit in the viewer
// redraws no shadow map.
#include <memory>
#include <string>

#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet {

class ShadowPassKey {
 public:
  ShadowPassKey() = default;  // matches no frame: nothing drawn yet
  ShadowPassKey(const Scene& scene, const FrameInputs& frame);

  // Whether the maps drawn for this key are those of `frame` on `scene`.
  bool matches(const Scene& scene, const FrameInputs& frame) const;

 private:
  std::weak_ptr<const char> scene_;  // Scene::identity's token
  std::string inputs_;               // the frame's values pass 1 reads, byte for byte
};

// The shadow pass's line in a frame's timings: "shadow pass (6 maps)", or
// "shadow pass (6 maps kept)" when the renderer kept the maps it had.
std::string shadowPassName(const FrameInputs& frame, bool kept);

}  // namespace facet
