#include "cpu/interpolation.h"

namespace facet::cpu {

Interpolation::Interpolation(const InterpolationVertex& a, const InterpolationVertex& b, const InterpolationVertex& c)
    : vertex_{a, b, c}, setup_(setUpPlanes(a.x, a.y, b.x, b.y, c.x, c.y)), z_(planeOf(setup_, a.z, b.z, c.z)) {}

void Interpolation::setUpMore(int count) {
  const InterpolationVertex &a = vertex_[0], &b = vertex_[1], &c = vertex_[2];
  oneOverW_ = planeOf(setup_, a.invW, b.invW, c.invW);
  count_ = count;
  for (int k = 0; k < count; ++k)
    varying_.plane[k] = planeOf(setup_, a.varyings[k] * a.invW, b.varyings[k] * b.invW, c.varyings[k] * c.invW);
}

Interpolation Interpolation::movedBy(float dx, float dy) const {
  const auto moved = [&](Plane p) {
    p.a0 = fusedMultiplyAdd(p.dady, dy, fusedMultiplyAdd(p.dadx, dx, p.a0));
    return p;
  };
  Interpolation out = *this;
  out.z_ = moved(z_);
  out.oneOverW_ = moved(oneOverW_);
  for (int k = 0; k < count_; ++k) out.varying_.plane[k] = moved(varying_.plane[k]);
  return out;
}

}  // namespace facet::cpu
