#pragma once
// Attribute interpolation at pixel centres: screen-space barycentric weights
// from the triangle's window coordinates; window z linear in screen space;
// every other attribute perspective-correct (weights divided by w,
// interpolated, renormalized), as the course and the contract prescribe.
#include <array>

#include "cpu/clipper.h"

namespace facet::cpu {

class Interpolation {
 public:
  Interpolation(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c);

  // Sets the weights for the centre of pixel (px, py); returns window z.
  float at(int px, int py);

  // Perspective-correct value of varying k at the current pixel.
  float varying(int k) const {
    const auto i = static_cast<std::size_t>(k);
    return perspective_[0] * v_[0]->varyings[i] + perspective_[1] * v_[1]->varyings[i] + perspective_[2] * v_[2]->varyings[i];
  }

 private:
  const WindowVertex* v_[3];
  // λ_i = base_[i] + dx_[i]·(x - x0) + dy_[i]·(y - y0), relative to the first
  // vertex (x0, y0) as llvmpipe sets up its planes: products of absolute
  // window coordinates would cancel catastrophically on small triangles.
  float x0_, y0_;
  float base_[3], dx_[3], dy_[3];
  std::array<float, 3> perspective_{};
};

}  // namespace facet::cpu
