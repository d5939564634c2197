#pragma once
// The ray-tracing backend (renderer/PIPELINE.md, "Ray tracing"): a third
// Renderer beside the rasterizers, taking the same Scene and FrameInputs.
// Pixels in 16 x 16 tiles on a pool of threads that lives as long as the
// renderer; the BVH is kept from frame to frame while the scene and its
// instances' transforms stay the same (the viewer's orbit).
#include <functional>
#include <memory>

#include "render/renderer.h"

namespace facet {

// How far a frame has come, in [0, 1], called now and then while it renders
// (from the calling thread): `facet render`'s progress bar.
using RenderProgress = std::function<void(double done)>;

// threads <= 0: one per core.
std::unique_ptr<Renderer> makeRayRenderer(int threads, RenderProgress progress = {});

// What the ray tracer refuses of a frame: the rasterizer's area-weighted
// averaging and its ray-cast volume. Throws facet::Error naming the settings
// key; the renderer calls it, and `render` before it starts one.
void refuseRayImage(const FrameInputs& frame);

}  // namespace facet
