#pragma once
// The course's pipeline one triangle at a time, written to be read: the
// readable reference of the CPU backend (renderer/cpu/reference/
// reference_renderer.cpp). It calls the same rules as the fast, tiled,
// threaded renderer (clipper, window transform, snapping and edge
// functions, plane equations, lighting) in their plainest order, shades
// every fragment that passes the z-buffer, and is held equal to the fast
// renderer pixel for pixel (tests/cpu/test_reference.cpp).
#include <memory>

#include "render/renderer.h"

namespace facet {

// One thread, no tiles, no batching; much slower than makeCpuRenderer.
std::unique_ptr<Renderer> makeReferenceRenderer();

// antialiasing.pattern=area: the frame by the course's area-weighted
// averaging (renderer/PIPELINE.md, section 7), the reference's vertex and
// fragment stages with exact coverage in place of pixel centres; the CPU
// backend draws such frames with it too. Throws facet::Error for what it
// does not cover (lines, points, the painter's order).
RenderResult renderAreaAveraged(const Scene& scene, const FrameInputs& frame);

}  // namespace facet
