#pragma once
#include <memory>

#include "render/renderer.h"

namespace facet {

// The CPU reference rasterizer: the pipeline of renderer/PIPELINE.md in
// software, covering the same pixels as llvmpipe. threads = 0: one per core.
std::unique_ptr<Renderer> makeCpuRenderer(int threads = 0);

}  // namespace facet
