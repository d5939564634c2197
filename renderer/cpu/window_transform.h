#pragma once
// Clip coordinates to window coordinates (the course's window-to-viewport
// mapping of NDC [-1, 1]² onto [0, W]×[0, H], depth range [0, 1]), with the
// roundings llvmpipe's two paths have (renderer/PIPELINE.md, "Rasterization"):
//   a vertex of the vertex stage:  x_w = fma(x·(1/w), W/2, W/2)   (its JIT fuses the multiply-add)
//   a vertex the clipper made:     x_w = (x·(1/w))·(W/2) + W/2    (draw_pipe_clip.c, in C: two roundings)
// the same for y with H; z_w = z·(1/w) (scale 1, offset 0); and 1/w is kept
// for perspective-correct interpolation.
#include <cmath>

#include <glm/vec4.hpp>

namespace facet::cpu {

struct WindowPosition {
  float x, y;  // pixels, origin lower left
  float z;     // window z = NDC z in [0, 1] inside the view volume
  float invW;  // 1/w_clip
};

inline WindowPosition windowPosition(const glm::vec4& clip, float halfWidth, float halfHeight, bool madeByClipper) {
  const float oneOverW = 1.0f / clip.w;
  const float xNdc = clip.x * oneOverW, yNdc = clip.y * oneOverW;
  if (madeByClipper) return {xNdc * halfWidth + halfWidth, yNdc * halfHeight + halfHeight, clip.z * oneOverW, oneOverW};
  return {std::fma(xNdc, halfWidth, halfWidth), std::fma(yNdc, halfHeight, halfHeight), clip.z * oneOverW, oneOverW};
}

}  // namespace facet::cpu
