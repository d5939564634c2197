#include "cpu/interpolation.h"

namespace facet::cpu {

Interpolation::Interpolation(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c)
    : v_{&a, &b, &c}, x0_(a.x), y0_(a.y) {
  const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  const float inverse = area != 0.0f ? 1.0f / area : 0.0f;
  for (int i = 0; i < 3; ++i) {
    // λ_i is the signed area of the sub-triangle opposite vertex i over the
    // whole, with p and q the other two vertices taken relative to vertex 0.
    const WindowVertex& p = *v_[(i + 1) % 3];
    const WindowVertex& q = *v_[(i + 2) % 3];
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
}

float Interpolation::at(int px, int py) {
  const float x = static_cast<float>(px) + 0.5f - x0_, y = static_cast<float>(py) + 0.5f - y0_;
  float lambda[3];
  for (int i = 0; i < 3; ++i) lambda[i] = base_[i] + dx_[i] * x + dy_[i] * y;
  const float w0 = lambda[0] * v_[0]->invW, w1 = lambda[1] * v_[1]->invW, w2 = lambda[2] * v_[2]->invW;
  const float sum = w0 + w1 + w2;
  const float inverse = sum != 0.0f ? 1.0f / sum : 0.0f;
  perspective_ = {w0 * inverse, w1 * inverse, w2 * inverse};
  // z0 + λ1·(z1 - z0) + λ2·(z2 - z0): the same value as Σ λ_i·z_i, but the
  // rounding of λ only scales the small differences. Window z crowds toward 1
  // under perspective, and Σ λ_i·z_i let far surfaces fight through near ones.
  const float z0 = v_[0]->z;
  return z0 + (lambda[1] * (v_[1]->z - z0) + lambda[2] * (v_[2]->z - z0));
}

}  // namespace facet::cpu
