#pragma once
// Homogeneous clipping as llvmpipe's draw module does it
// (src/gallium/auxiliary/draw/draw_pipe_clip.c, do_clip_tri; clip masks from
// draw_llvm.c generate_clipmask), so that the CPU reference produces the same
// window vertices, and therefore the same covered pixels, as OpenGL on llvmpipe.
#include <array>
#include <vector>

#include <glm/vec4.hpp>

#include "shading/lit_varyings.h"  // kMaxVaryings

namespace facet::cpu {


// A vertex after the vertex stage: clip position and the attributes that
// are interpolated across the triangle.
struct ClipVertex {
  glm::vec4 clip{0.0f};
  std::array<float, kMaxVaryings> varyings{};
};

// A vertex as triangle setup sees it.
struct WindowVertex {
  float x = 0, y = 0;   // window coordinates, pixels, origin lower left
  float z = 0;          // window z = NDC z in [0, 1]
  float invW = 1;       // 1/w_clip, for perspective-correct interpolation
  std::array<float, kMaxVaryings> varyings{};
};

// Window coordinates of an unclipped vertex (window_transform.h).
WindowVertex toWindow(const ClipVertex& v, float halfWidth, float halfHeight, int varyingCount);

// Clips triangle (a, b, c) against -w ≤ x ≤ w, -w ≤ y ≤ w, 0 ≤ z ≤ w and
// appends the triangles to draw, three WindowVertex each, to `out`:
// the triangle itself when no vertex is outside (with `windowA..C`, its
// already-computed window vertices), nothing when all three are outside one
// plane, else the clipped polygon as a fan (v[i-1], v[i], v[0]).
void clipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, const WindowVertex& windowA,
                  const WindowVertex& windowB, const WindowVertex& windowC, float halfWidth, float halfHeight, int varyingCount,
                  std::vector<WindowVertex>& out);

// Clips segment (a, b) as draw's do_clip_line: for each plane it crosses,
// t0 and t1 (how much of each end is cut) grow to the largest cut; nothing
// is left when t0 + t1 ≥ 1 or a distance is not finite. An end outside
// becomes a + t0·(b - a) (b's likewise), with the clipper's window
// arithmetic; an end inside keeps `windowA` / `windowB`. False when nothing is left.
bool clipSegment(const ClipVertex& a, const ClipVertex& b, const WindowVertex& windowA, const WindowVertex& windowB, float halfWidth,
                 float halfHeight, int varyingCount, WindowVertex& outA, WindowVertex& outB);

// The clip mask of one vertex: bit i set when it is outside plane i (order
// above). Inline: the vertex stage asks it of every vertex (a call each was
// 1.6 % of a sphere-1m frame's instructions).
inline unsigned clipMask(const glm::vec4& p) {
  unsigned m = 0;
  if (p.x > p.w) m |= 1u;
  if (0.0f > p.x + p.w) m |= 2u;
  if (p.y > p.w) m |= 4u;
  if (0.0f > p.y + p.w) m |= 8u;
  if (0.0f > p.z) m |= 16u;
  if (p.z > p.w) m |= 32u;
  return m;
}

}  // namespace facet::cpu
