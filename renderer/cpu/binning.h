#pragma once
// Phase 2 of a pass (frame_buffers.h): clip, snap, cull and bin the
// triangles [begin, end) of the frame's triangle list, in order.
#include <cstddef>
#include "common/function_ref.h"

#include "cpu/frame_buffers.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet::cpu {

// Flat shading's per-triangle illumination (front, back) from the triangle's
// three vertices (indices into PassVertices); called once for each triangle that reaches setup.
// `culling`: back faces of the instances that FrameInstance::cullBackFaces
// marks are dropped (the lit pass); false keeps every triangle (the shadow pass).
// `order`: positions [begin, end) of this list of triangle indices are binned
// (the painter's order); null: the triangles [begin, end) themselves.
using FlatIllumination = FunctionRef<void(std::uint32_t instance, const std::uint32_t (&indices)[3], Illumination (&out)[2])>;

void binTriangles(const Scene& scene, const FrameInputs& frame, const PassVertices& vertices, const TileGrid& grid, bool culling,
                  std::size_t begin, std::size_t end, WorkerBins& bins, const FlatIllumination* flat, const std::uint32_t* order = nullptr);

// Packs the window vertex of an unclipped vertex with clip coordinates
// `clip` (window_transform.h) into out[0..3]: x, y, z, 1/w.
inline void packWindow(const glm::vec4& clip, float halfWidth, float halfHeight, float* out);

}  // namespace facet::cpu

#include <cmath>

#include "cpu/window_transform.h"

namespace facet::cpu {

inline void packWindow(const glm::vec4& clip, float halfWidth, float halfHeight, float* out) {
  const WindowPosition p = windowPosition(clip, halfWidth, halfHeight, false);
  out[0] = p.x, out[1] = p.y, out[2] = p.z, out[3] = p.invW;
}

inline std::uint8_t vertexFlags(const glm::vec4& p) {
  const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
  return static_cast<std::uint8_t>(clipMask(p) | (finite ? 0u : kNotFinite));
}

}  // namespace facet::cpu
