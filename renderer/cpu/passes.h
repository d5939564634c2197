#pragma once
// The two passes of a CPU frame (the course's 2-pass shadow algorithm):
// pass 1 renders each shadow-casting light's depth maps, pass 2 shades the
// image. Rows [rowBegin, rowEnd) let several threads split one target; each
// pixel is written by one thread, in triangle order, so results do not
// depend on the thread count.
#include <vector>

#include "cpu/shadow_maps.h"
#include "image/image.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet::cpu {

// Pass 1 for one face layer: depth of every triangle (no culling), LESS.
void shadowPass(const Scene& scene, const FrameInputs& frame, const FrameLight& light, int face, int rowBegin, int rowEnd,
                ShadowMaps& maps);

// Pass 2: z-buffer and shading into `image` (cleared by the caller to the
// background) and `depth` (cleared to 1).
void litPass(const Scene& scene, const FrameInputs& frame, const ShadowMaps& maps, int rowBegin, int rowEnd, Image& image,
             std::vector<float>& depth);

}  // namespace facet::cpu
