#pragma once
// The course's scanline z-buffer, hsr = scanline (renderer/PIPELINE.md,
// "Hidden-surface removal"): one row of depth at a time instead of
// a frame of it. Polygons (the binned triangles, after clipping, snapping and
// culling) are bucketed by y_min; each scanline adds its bucket to the active
// polygon list and drops the polygons past their y_max; each active polygon's
// span comes from its edges' x-intercepts, stepped from row to row
// (x_{y+1} = x_y + 1/m, exact in integers), and its depth is stepped along
// the span (z_{x+1} = z_x - A/C). The pixel keeps what the z-buffer keeps.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cpu/frame_buffers.h"
#include "common/thread_pool.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet::cpu {

inline constexpr std::uint32_t kNoPolygon = 0xffffffffu;

// The binned triangles of all workers numbered in submission order (worker
// 0's first): polygon p is workers[w].triangles[p - first[w]].
struct PolygonNumbering {
  std::vector<std::size_t> first;  // per worker, then the total

  explicit PolygonNumbering(const std::vector<WorkerBins>& workers);
  std::size_t count() const { return first.back(); }
  // The worker whose bins hold polygon p.
  std::size_t workerOf(std::uint32_t p) const;
};

// The polygon each pixel keeps (width × height, bottom row first; kNoPolygon
// for the background): the one the z-buffer would keep, LESS in submission
// order with the alpha mask, pixel for pixel. The rows are split between the
// pool's workers, each with its own row of depth.
void scanlineVisibility(ThreadPool& pool, const std::vector<WorkerBins>& workers, const PassVertices& vertices, const Scene& scene,
                        const FrameInputs& frame, const PolygonNumbering& numbering, std::vector<std::uint32_t>& visible);

// The bytes of depth the scanline z-buffer keeps with `workers` rows of `width`.
std::size_t scanlineDepthBytes(int width, int workers);

}  // namespace facet::cpu
