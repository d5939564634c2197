#include "cpu/interpolation.h"

namespace facet::cpu {
namespace {

InterpolationVertex view(const WindowVertex& v) { return {v.x, v.y, v.z, v.invW, v.varyings.data()}; }

}  // namespace

Interpolation::Interpolation(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c) { setUp(view(a), view(b), view(c)); }

Interpolation::Interpolation(const InterpolationVertex& a, const InterpolationVertex& b, const InterpolationVertex& c) { setUp(a, b, c); }

void Interpolation::setUp(const InterpolationVertex& a, const InterpolationVertex& b, const InterpolationVertex& c) {
  const InterpolationVertex* v[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    varyings_[i] = v[i]->varyings;
    invW_[i] = v[i]->invW;
  }
  x0_ = a.x;
  y0_ = a.y;
  const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  const float inverse = area != 0.0f ? 1.0f / area : 0.0f;
  for (int i = 0; i < 3; ++i) {
    // λ_i is the signed area of the sub-triangle opposite vertex i over the
    // whole, with p and q the other two vertices taken relative to vertex 0.
    const InterpolationVertex& p = *v[(i + 1) % 3];
    const InterpolationVertex& q = *v[(i + 2) % 3];
    const float px = p.x - x0_, py = p.y - y0_, qx = q.x - x0_, qy = q.y - y0_;
    dx_[i] = (py - qy) * inverse;
    dy_[i] = (qx - px) * inverse;
    base_[i] = (px * qy - qx * py) * inverse;
  }
  if (area == 0.0f) {  // only for slivers the fixed-point grid still sees: use the centroid
    for (int i = 0; i < 3; ++i) {
      dx_[i] = dy_[i] = 0.0f;
      base_[i] = 1.0f / 3.0f;
    }
  }
  // z0 + λ1·(z1 - z0) + λ2·(z2 - z0): the same value as Σ λ_i·z_i, but the
  // rounding of λ only scales the small differences. Window z crowds toward 1
  // under perspective, and Σ λ_i·z_i let far surfaces fight through near ones.
  z0_ = a.z;
  dz1_ = b.z - z0_;
  dz2_ = c.z - z0_;
}

}  // namespace facet::cpu
