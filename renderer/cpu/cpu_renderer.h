#pragma once
#include <memory>

#include "render/renderer.h"

namespace facet {

// The CPU reference rasterizer: the pipeline of renderer/PIPELINE.md in
// software, covering the same pixels as llvmpipe. threads = 0: one per core.
// lanes: pixels Phong's lighting takes at a time (common/lane_width.h), 8
// (AVX2), 4 or 1; 0: the widest this CPU runs. Every width gives the same image.
std::unique_ptr<Renderer> makeCpuRenderer(int threads = 0, int lanes = 0);

}  // namespace facet
