#pragma once
// Phong shading's per-pixel illumination four pixels at a time (SSE2, part of
// every x86-64 CPU). Each lane performs exactly the float operations of
// illuminate(), shade() and viewVector() in lighting.h, in the same order and
// with the same roundings (no fused multiply-add; glm's normalize is
// v·(1/sqrt(v·v)), its dot (x + y) + z), so the result is bit-identical to
// the scalar code; tests/cpu/test_fast_paths.cpp holds the two against each
// other. What is not arithmetic on four lanes stays scalar per lane: the
// shadow factor (texel reads) and pow (the C library's powf, as the scalar
// code calls it). The light loop is the same for every lane; a light that
// `continue`s for one lane leaves that lane's sums untouched (a select, not
// an add of zero). Without SSE2 the batch calls the scalar functions.
#include <cstdint>

#include "cpu/lighting.h"
#include "cpu/srgb_table.h"
#include "image/image.h"

namespace facet::cpu {

class PhongBatch {
 public:
  static constexpr int kLanes = 4;

  PhongBatch(const FrameInputs& frame, const ShadowMaps& maps, Rgba8* pixels)
      : frame_(frame), maps_(maps), srgb_(srgbTable()), pixels_(pixels) {}

  // Queues the pixel at pixels[offset]: world position P, the interpolated
  // normal (normalized here, and negated for a back face, as the scalar path
  // does), O_d and the material; shades when four are queued.
  void add(std::size_t offset, glm::vec3 P, glm::vec3 interpolatedNormal, bool back, glm::vec3 baseColor, const CourseMaterial& material) {
    const int k = count_++;
    offset_[k] = offset;
    for (int c = 0; c < 3; ++c) {
      P_[c][k] = P[c];
      N_[c][k] = interpolatedNormal[c];
      O_[c][k] = baseColor[c];
    }
    back_[k] = back ? -0.0f : 0.0f;  // the sign bit to flip
    material_[k] = &material;
    if (count_ == kLanes) flush();
  }

  // Shades what is queued.
  void flush();

 private:
  const FrameInputs& frame_;
  const ShadowMaps& maps_;
  const SrgbTable& srgb_;
  Rgba8* pixels_;
  int count_ = 0;
  std::size_t offset_[kLanes];
  const CourseMaterial* material_[kLanes];
  alignas(16) float P_[3][kLanes], N_[3][kLanes], O_[3][kLanes], back_[kLanes];
  alignas(16) float E_[3][kLanes], ka_[kLanes], kd_[kLanes], ks_[kLanes], n_[kLanes];  // filled by flush
};

}  // namespace facet::cpu
