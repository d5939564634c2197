#pragma once
// The painter's algorithm's order (renderer/PIPELINE.md, "Rasterization",
// "Hidden-surface removal"): every triangle of the frame, farthest first.
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace facet {

struct FrameInputs;

// The frame's triangles (indices in its triangle list: instances in order,
// each mesh's triangles in order) sorted by their farthest eye depth,
// largest first: d = z_eye of EM·TM·p (the course's eye space looks along
// +z), the largest of the three vertices',
// in double precision. Equal depths keep the triangle list's order; a
// triangle whose depth is not a number comes first (the rasterizers drop it).
std::vector<std::uint32_t> paintersOrder(const Scene& scene, const FrameInputs& frame);

// The painter's key d of every triangle of the frame, in its triangle list's
// order: +infinity where a vertex's depth is not a number.
std::vector<double> farthestEyeDepths(const Scene& scene, const FrameInputs& frame);

}  // namespace facet
