#pragma once
// facet bench --backends ray: beside the ray tracer's frame time, its rays by
// kind (primary, shadow, secondary) traced alone through facet's BVH, the
// BVH's build time and memory, and, where the build found Intel Embree 3
// (Debian's libembree-dev), the same rays through Embree in the same run:
// a peer kept here in the bench code, not a backend of facet's.
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet {

// Prints the table for one bench scene: medians over `frames` runs of each
// kind, `threads` workers each for facet and for Embree.
void printRayRates(const Scene& scene, const FrameInputs& frame, int threads, int frames);

}  // namespace facet
