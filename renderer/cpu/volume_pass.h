#pragma once
// Volume ray casting over a drawn frame (renderer/PIPELINE.md, "Volume rendering",
// "Ray casting"): each pixel's ray through the volume, from the near plane
// to the opaque surface the z-buffer kept there, composited over the pixel.
#include <vector>

#include "cpu/passes.h"
#include "image/color_buffer.h"
#include "pipeline/frame_inputs.h"
#include "volume/volume_raycast.h"

namespace facet::cpu {

// `depth`: each pixel's window z after the opaque surfaces (1 where none).
// The volume's premultiplied (C, A) goes over what the buffer holds:
// C_o = C + (1 − A)·C_b·α_b, α_o = A + (1 − A)·α_b, stored as the frame's blending holds colours.
RayCastCounts volumePass(ThreadPool& pool, const FrameInputs& frame, const std::vector<float>& depth, ColorBuffer& color);

}  // namespace facet::cpu
