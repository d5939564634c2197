#pragma once
// antialiasing.pattern=area: a frame by the course's area-weighted averaging
// (renderer/PIPELINE.md, "Area-weighted averaging"): pass 2's
// triangles, through the lit programs' vertex and fragment stages, with
// each pixel's exact coverage (area_averaging.h) in place of its centre.
#include "render/renderer.h"
#include "shading/shadow_maps.h"

namespace facet::cpu {

// The image of the frame, lit with pass 1's `maps`. Throws facet::Error for
// what it does not cover (lines, points, the painter's order).
RenderResult renderAreaAveraged(const Scene& scene, const FrameInputs& frame, const ShadowMaps& maps);

}  // namespace facet::cpu
