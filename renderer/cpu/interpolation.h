#pragma once
// Attribute interpolation at pixel centres: screen-space barycentric weights
// from the triangle's window coordinates; window z linear in screen space;
// every other attribute perspective-correct (weights divided by w,
// interpolated, renormalized), as the course and the contract prescribe.
#include <array>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "cpu/clipper.h"

namespace facet::cpu {

// What interpolation reads of a window vertex; `varyings` points at its
// attributes (a WindowVertex's, or a packed vertex of the frame's buffers).
struct InterpolationVertex {
  float x, y, z, invW;
  const float* varyings;
};

class Interpolation {
 public:
  Interpolation(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c);
  Interpolation(const InterpolationVertex& a, const InterpolationVertex& b, const InterpolationVertex& c);

  // Sets the weights for the centre of pixel (px, py); returns window z.
  float at(int px, int py);

  // Window z at the centre of pixel (px, py): the value at() returns, without the weights.
  float depthAt(int px, int py) const {
    const float x = static_cast<float>(px) + 0.5f - x0_, y = static_cast<float>(py) + 0.5f - y0_;
    const float lambda1 = base_[1] + dx_[1] * x + dy_[1] * y;
    const float lambda2 = base_[2] + dx_[2] * x + dy_[2] * y;
    return z0_ + (lambda1 * dz1_ + lambda2 * dz2_);
  }

  // varying(k) for k in [0, count), four at a time where SSE2 is there (the
  // same products and sums per varying, so the same bits).
  void varyings(int count, float* out) const;

#if defined(__SSE2__)
  // at()'s perspective weights for the four pixels (px .. px+3, py), one per
  // lane, by the same operations; and varying(k) for them.
  void weights4(int px, int py, __m128 (&perspective)[3]) const;
  __m128 varying4(int k, const __m128 (&perspective)[3]) const {
    const auto i = static_cast<std::size_t>(k);
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(perspective[0], _mm_set1_ps(varyings_[0][i])), _mm_mul_ps(perspective[1], _mm_set1_ps(varyings_[1][i]))),
                      _mm_mul_ps(perspective[2], _mm_set1_ps(varyings_[2][i])));
  }
#endif

  // Perspective-correct value of varying k at the current pixel.
  float varying(int k) const {
    const auto i = static_cast<std::size_t>(k);
    return perspective_[0] * varyings_[0][i] + perspective_[1] * varyings_[1][i] + perspective_[2] * varyings_[2][i];
  }

 private:
  void setUp(const InterpolationVertex& a, const InterpolationVertex& b, const InterpolationVertex& c);

  const float* varyings_[3];
  float invW_[3];
  // λ_i = base_[i] + dx_[i]·(x - x0) + dy_[i]·(y - y0), relative to the first
  // vertex (x0, y0) as llvmpipe sets up its planes: products of absolute
  // window coordinates would cancel catastrophically on small triangles.
  float x0_, y0_;
  float base_[3], dx_[3], dy_[3];
  // z0 and z_i - z0 (i = 1, 2)
  float z0_, dz1_, dz2_;
  std::array<float, 3> perspective_{};
};

// Inline: the fragment stage calls it once per pixel.
inline float Interpolation::at(int px, int py) {
  const float x = static_cast<float>(px) + 0.5f - x0_, y = static_cast<float>(py) + 0.5f - y0_;
  float lambda[3];
  for (int i = 0; i < 3; ++i) lambda[i] = base_[i] + dx_[i] * x + dy_[i] * y;
  const float w0 = lambda[0] * invW_[0], w1 = lambda[1] * invW_[1], w2 = lambda[2] * invW_[2];
  const float sum = w0 + w1 + w2;
  const float inverse = sum != 0.0f ? 1.0f / sum : 0.0f;
  perspective_ = {w0 * inverse, w1 * inverse, w2 * inverse};
  return z0_ + (lambda[1] * dz1_ + lambda[2] * dz2_);
}

#if defined(__SSE2__)
inline void Interpolation::weights4(int px, int py, __m128 (&perspective)[3]) const {
  const __m128 x = _mm_sub_ps(_mm_add_ps(_mm_cvtepi32_ps(_mm_setr_epi32(px, px + 1, px + 2, px + 3)), _mm_set1_ps(0.5f)), _mm_set1_ps(x0_));
  const float y = static_cast<float>(py) + 0.5f - y0_;
  __m128 w[3];
  for (int i = 0; i < 3; ++i) {
    const __m128 lambda = _mm_add_ps(_mm_add_ps(_mm_set1_ps(base_[i]), _mm_mul_ps(_mm_set1_ps(dx_[i]), x)), _mm_set1_ps(dy_[i] * y));
    w[i] = _mm_mul_ps(lambda, _mm_set1_ps(invW_[i]));
  }
  const __m128 sum = _mm_add_ps(_mm_add_ps(w[0], w[1]), w[2]);
  // sum != 0 ? 1/sum : 0
  const __m128 inverse = _mm_andnot_ps(_mm_cmpeq_ps(sum, _mm_setzero_ps()), _mm_div_ps(_mm_set1_ps(1.0f), sum));
  for (int i = 0; i < 3; ++i) perspective[i] = _mm_mul_ps(w[i], inverse);
}
#endif

inline void Interpolation::varyings(int count, float* out) const {
  int k = 0;
#if defined(__SSE2__)
  const __m128 p0 = _mm_set1_ps(perspective_[0]), p1 = _mm_set1_ps(perspective_[1]), p2 = _mm_set1_ps(perspective_[2]);
  for (; k + 4 <= count; k += 4) {
    const __m128 sum = _mm_add_ps(_mm_add_ps(_mm_mul_ps(p0, _mm_loadu_ps(varyings_[0] + k)), _mm_mul_ps(p1, _mm_loadu_ps(varyings_[1] + k))),
                                  _mm_mul_ps(p2, _mm_loadu_ps(varyings_[2] + k)));
    _mm_storeu_ps(out + k, sum);
  }
#endif
  for (; k < count; ++k) out[k] = varying(k);
}

}  // namespace facet::cpu
