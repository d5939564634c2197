#pragma once
// The course's pipeline one triangle at a time, written to be read: the
// readable reference of the CPU backend (renderer/cpu/reference/
// reference_renderer.cpp). It calls the same rules and programs as the
// fast, tiled, threaded renderer (clipper, window transform, snapping and
// edge functions, plane equations, shading/lit_programs.h) in their
// plainest order, shades every fragment that passes the z-buffer, and is
// held equal to the fast renderer pixel for pixel (tests/cpu/test_reference.cpp).
#include <memory>

#include "render/renderer.h"

namespace facet {

// One thread, no tiles, no batching; much slower than makeCpuRenderer.
std::unique_ptr<Renderer> makeReferenceRenderer();

// What the reference refuses of a frame whose image it is asked for: more
// than one sample a pixel, hidden-surface removal other than the z-buffer,
// a ray-cast volume, area-weighted averaging. Throws facet::Error naming the
// settings key; the renderer calls it, and `render` before it loads one.
void refuseReferenceImage(const FrameInputs& frame);

}  // namespace facet
