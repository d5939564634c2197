#pragma once
// Attribute interpolation at pixel centres with llvmpipe's plane equations
// (plane_equations.h): window z linear in screen space, every other
// attribute perspective-correct (the plane of a·(1/w), times 1/w at the
// pixel), as the course, the contract and renderer/PIPELINE.md, "Rasterization" say.

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "cpu/clipper.h"
#include "cpu/plane_equations.h"
#include "shading/draw_uniforms.h"
#include "shading/lit_varyings.h"

namespace facet::cpu {

// What interpolation reads of a window vertex; `varyings` points at its
// attributes (a WindowVertex's, or a packed vertex of the frame's buffers).
struct InterpolationVertex {
  float x, y, z, invW;
  const float* varyings;
};

// One triangle's planes: window z at once, 1/w and the varyings when asked
// (only triangles that keep a pixel are shaded).
class Interpolation {
 public:
  Interpolation() = default;
  // The triangle's vertices in set-up order (triangle_setup.h).
  Interpolation(const InterpolationVertex& a, const InterpolationVertex& b, const InterpolationVertex& c);

  // Window z at pixel (px, py)'s centre, clamped to [0, 1]: what the z-buffer tests and keeps.
  float depthAt(int px, int py) const { return cpu::depthAt(z_, px, py); }
  // The plane depthAt evaluates (the scanline z-buffer steps along it).
  const Plane& depthPlane() const { return z_; }
  // The interpolated 1/w at pixel (px, py) (fog's eye depth); after setUpVaryings.
  float oneOverWAt(int px, int py) const { return oneOverW_.at(px, py); }

  // Sets up the planes of 1/w and of varyings [0, count), before the calls
  // below; a call for no more varyings than are set up does nothing (a tile
  // meets a triangle's pixels row after row, in runs between other triangles').
  void setUpVaryings(int count) {
    if (count > count_) setUpMore(count);  // inline: the shading loop asks again at every change of triangle
  }

  // The same planes with each one's value at pixel (0, 0)'s centre moved to
  // fma(dady, dy, fma(dadx, dx, a(0))), so that every call below at (px, py)
  // gives the value at (px + dx, py + dy): area-weighted averaging shades a
  // cell at its centroid this way, as a sample's pass at that offset would.
  Interpolation movedBy(float dx, float dy) const;

  // The varyings set up at pixel (px, py): plane(a·(1/w)) · (1 / plane(1/w)).
  void varyingsAt(int px, int py, float* out) const {
    const float w = 1.0f / oneOverW_.at(px, py);
    for (int k = 0; k < count_; ++k) out[k] = varying_.plane[k].at(px, py) * w;
  }

  // Varying k at pixel (px, py), by the operations of varyingsAt.
  float varyingAt(int k, int px, int py) const { return varying_.plane[k].at(px, py) * (1.0f / oneOverW_.at(px, py)); }
  // 1 / plane(1/w) at pixel (px, py), and varyings k .. k+2 with it, by the operations of varyingsAt
  // (in registers: a varying read back from varyingsAt's stores a pair at a time waits on store forwarding).
  float inverseWAt(int px, int py) const { return 1.0f / oneOverW_.at(px, py); }
  glm::vec3 varying3At(int k, int px, int py, float inverseW) const {
    const auto at = [&](int j) { return varying_.plane[j].at(px, py) * inverseW; };
    return {at(k), at(k + 1), at(k + 2)};
  }

  // dFdx and dFdy of varyings k, k + 1 as llvmpipe computes them
  // (PIPELINE.md, "Textures"): differences within the pixel's 2×2 quad, per
  // row for x and per column for y, at pixels inside the triangle or not.
  // (d(k)/dx, d(k+1)/dx, d(k)/dy, d(k+1)/dy).
  glm::vec4 quadDerivatives(int k, int px, int py) const {
    const int qx = px & ~1, qy = py & ~1;
    return {varyingAt(k, qx + 1, py) - varyingAt(k, qx, py), varyingAt(k + 1, qx + 1, py) - varyingAt(k + 1, qx, py),
            varyingAt(k, px, qy + 1) - varyingAt(k, px, qy), varyingAt(k + 1, px, qy + 1) - varyingAt(k + 1, px, qy)};
  }

  // The planes themselves: 1/w's, and varying k's (after setUpVaryings), for a wider evaluation of the same operations.
  const Plane& oneOverWPlane() const { return oneOverW_; }
  const Plane& varyingPlane(int k) const { return varying_.plane[k]; }

 private:
  void setUpMore(int count);

  InterpolationVertex vertex_[3]{};
  PlaneSetup setup_;
  Plane z_, oneOverW_;
  int count_ = -1;  // varyings set up; -1: not 1/w either
  // The planes of varyings [0, count_), set up by setUpMore. The others are
  // never read and are left uninitialized: zeroing all of them (276 bytes)
  // for every triangle of every tile took 2 % of a sphere-1m frame.
  union Planes {
    Planes() {}  // no member initialized
    Plane plane[kMaxVaryings];
  } varying_;
};

// The point of a surface the varyings set up on `in` describe at pixel (px,
// py), in `mode`'s layout (the first `used`; shading/lit_varyings.h), seen
// from `front`, flat's face illumination from `flat`; with the quad
// derivatives of the texture coordinate sets the draw's maps sample.
inline SurfacePoint surfacePointAt(const Interpolation& in, const DrawUniforms& d, ShadingMode mode, int used, bool front, const Illumination* flat,
                                   int px, int py) {
  float v[kMaxVaryings];
  if (used) in.varyingsAt(px, py, v);
  SurfacePoint p = surfacePointOf(mode, v, used, front, flat);
  for (int set = 0; set < 2; ++set)
    if (d.samplesSet[set]) p.derivatives[set] = in.quadDerivatives(varyingLayout(mode).texcoord(set), px, py);
  return p;
}

}  // namespace facet::cpu
