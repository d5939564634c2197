#pragma once
// The ray-tracing backend (renderer/PIPELINE.md, section 10): a third
// Renderer beside the rasterizers, taking the same Scene and FrameInputs.
// Pixels in 16 x 16 tiles on a pool of threads that lives as long as the
// renderer; the BVH is kept from frame to frame while the scene and its
// instances' transforms stay the same (the viewer's orbit).
#include <memory>

#include "render/renderer.h"

namespace facet {

// threads <= 0: one per core.
std::unique_ptr<Renderer> makeRayRenderer(int threads);

}  // namespace facet
