#pragma once
// Depth and attributes across a triangle as llvmpipe computes them, so that
// both backends get the same bits (renderer/PIPELINE.md, "Depth
// and attributes"). Read from Mesa 22.3: lp_state_setup.c (init_args,
// calc_coef4: the set-up, once per triangle) and lp_bld_interp.c
// (attribs_update_simple: the value at a pixel).
//
// Set-up, from the window x, y of the triangle's vertices in the order
// llvmpipe hands them to its set-up (triangle_setup.h: the first two swapped
// when the fixed-point area is negative):
//
//   e = (x0 - x1)·(y2 - y0),  f = (y0 - y1)·(x2 - x0),  ooa = 1/(e - f)
//   for an attribute with vertex values a0, a1, a2:
//     da01 = a0 - a1,  da20 = a2 - a0
//     dadx = da01·((y2 - y0)·ooa) - da20·((y0 - y1)·ooa)
//     dady = da20·((x0 - x1)·ooa) - da01·((x2 - x0)·ooa)
//     a(0) = a0 - (dadx·(x0 - 0.5) + dady·(y0 - 0.5))     the value at pixel (0, 0)'s centre
//
// each product and sum rounded on its own (llvmpipe emits plain fmul, fsub).
// At pixel (px, py): a = fma(dady, py, fma(dadx, px, a(0))), two fused
// multiply-adds (llvm.fmuladd, fused on CPUs with FMA). Window z is such a
// plane, then clamped to [0, 1] (GL's depth range; min before max, x86
// semantics, so NaN becomes 1). A perspective-correct attribute is the plane
// of a_i·(1/w_i), times 1/w_plane, where w_plane is the plane of the 1/w_i:
// one division, one product.
#include "shading/lanes.h"  // fusedMultiplyAdd, minX86, maxX86

namespace facet::cpu {

// The per-triangle part of the set-up.
struct PlaneSetup {
  float x0Centre = 0, y0Centre = 0;  // vertex 0 relative to pixel (0, 0)'s centre: x0 - 0.5, y0 - 0.5
  float dx01 = 0, dy01 = 0;          // (x0 - x1)·ooa, (y0 - y1)·ooa
  float dx20 = 0, dy20 = 0;          // (x2 - x0)·ooa, (y2 - y0)·ooa
};

// One attribute's plane: its value at pixel (0, 0)'s centre and its steps per pixel.
struct Plane {
  float a0 = 0, dadx = 0, dady = 0;

  float at(int px, int py) const {
    return fusedMultiplyAdd(dady, static_cast<float>(py), fusedMultiplyAdd(dadx, static_cast<float>(px), a0));
  }
};

// Window x, y of the three vertices, in llvmpipe's set-up order.
inline PlaneSetup setUpPlanes(float x0, float y0, float x1, float y1, float x2, float y2) {
  const float dx01 = x0 - x1, dy01 = y0 - y1;
  const float dx20 = x2 - x0, dy20 = y2 - y0;
  const float e = dx01 * dy20, f = dy01 * dx20;
  const float ooa = 1.0f / (e - f);
  PlaneSetup s;
  s.x0Centre = x0 - 0.5f;
  s.y0Centre = y0 - 0.5f;
  s.dx01 = dx01 * ooa;
  s.dy01 = dy01 * ooa;
  s.dx20 = dx20 * ooa;
  s.dy20 = dy20 * ooa;
  return s;
}

inline Plane planeOf(const PlaneSetup& s, float a0, float a1, float a2) {
  const float da01 = a0 - a1, da20 = a2 - a0;
  Plane p;
  p.dadx = da01 * s.dy20 - da20 * s.dy01;
  p.dady = da20 * s.dx01 - da01 * s.dx20;
  p.a0 = a0 - (p.dadx * s.x0Centre + p.dady * s.y0Centre);
  return p;
}

#if defined(__SSE2__)
// Plane::at for the four pixels (px .. px+3, py), one per lane.
inline __m128 planeAt4(const Plane& p, int px, int py) {
  const __m128 x = _mm_add_ps(_mm_set1_ps(static_cast<float>(px)), _mm_setr_ps(0.0f, 1.0f, 2.0f, 3.0f));
  return fusedMultiplyAdd4(_mm_set1_ps(p.dady), _mm_set1_ps(static_cast<float>(py)), fusedMultiplyAdd4(_mm_set1_ps(p.dadx), x, _mm_set1_ps(p.a0)));
}
#endif

// Window z as the depth test sees it: the plane's value clamped to [0, 1].
inline float depthAt(const Plane& z, int px, int py) { return maxX86(minX86(z.at(px, py), 1.0f), 0.0f); }

}  // namespace facet::cpu
