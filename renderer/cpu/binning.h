#pragma once
// Phase 2 of a pass (frame_buffers.h): clip, snap, cull and bin the
// triangles [begin, end) of the frame's triangle list, in order.
#include <cstddef>
#include "cpu/function_ref.h"

#include "cpu/frame_buffers.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet::cpu {

// Flat shading's per-triangle illumination (front, back) from the triangle's
// three vertices (indices into PassVertices); called once for each triangle that reaches setup.
using FlatIllumination = FunctionRef<void(std::uint32_t instance, const std::uint32_t (&indices)[3], Illumination (&out)[2])>;

void binTriangles(const Scene& scene, const FrameInputs& frame, const PassVertices& vertices, const TileGrid& grid, bool cullBackFaces,
                  std::size_t begin, std::size_t end, WorkerBins& bins, const FlatIllumination* flat);

// Snapping, signed area, orientation and pixel bounding box of the triangle
// with packed window vertices a, b, c (x, y first), as setupTriangle
// (triangle_setup.h) defines them: X, Y in llvmpipe's clockwise order, box =
// {minX, minY, maxX, maxY} clamped to the target. False where setupTriangle
// is false (zero area, nothing in the target, coordinates beyond 2^22).
bool snapTriangle(const float* a, const float* b, const float* c, int width, int height, BinnedTriangle& t, bool& frontFacing, int (&box)[4]);

// Packs the window vertex of clip coordinates `clip` (toWindow's arithmetic)
// into out[0..3]: x, y, z, 1/w.
inline void packWindow(const glm::vec4& clip, float halfWidth, float halfHeight, float* out);

}  // namespace facet::cpu

#include <cmath>

namespace facet::cpu {

inline void packWindow(const glm::vec4& clip, float halfWidth, float halfHeight, float* out) {
  const float oneOverW = 1.0f / clip.w;
  out[0] = std::fma(clip.x * oneOverW, halfWidth, halfWidth);
  out[1] = std::fma(clip.y * oneOverW, halfHeight, halfHeight);
  out[2] = clip.z * oneOverW;
  out[3] = oneOverW;
}

inline std::uint8_t vertexFlags(const glm::vec4& p) {
  const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
  return static_cast<std::uint8_t>(clipMask(p) | (finite ? 0u : kNotFinite));
}

}  // namespace facet::cpu
