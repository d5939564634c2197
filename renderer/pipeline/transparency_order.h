#pragma once
// The order blended triangles are drawn in (renderer/PIPELINE.md, "Shading",
// "Transparency"): after every opaque one, back to front.
#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

struct FrameInputs;

// The blended triangles of the frame (indices in its triangle list), farthest
// first. `object`: the blended instances by the eye depth of their world
// bounding box's centre, each instance's triangles in their order; `triangle`:
// each triangle by the painter's key (painters_order.h). Equal keys keep the
// list's order; a key that is not a number comes first.
std::vector<std::uint32_t> transparentOrder(const Scene& scene, const FrameInputs& frame, TransparencySort sort);

}  // namespace facet
