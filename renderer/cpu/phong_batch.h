#pragma once
// Phong shading's per-pixel illumination four pixels at a time: the lanes of
// lighting.h's illuminate<Float4>, shade and viewVector, the same code as one
// pixel's illuminate<float> (lanes.h: every operation the same IEEE
// operation per lane), so the result is bit-identical to shading each pixel
// alone; tests/cpu/test_fast_paths.cpp holds the two against each other.
// Pixels of different triangles and materials share a batch. Without SSE2
// the batch shades its pixels one by one.
#include <cstdint>

#include "cpu/lighting.h"
#include "image/color_buffer.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace facet::cpu {

class PhongBatch {
 public:
  static constexpr int kLanes = 4;  // add4 and flush assume four

  PhongBatch(const FrameInputs& frame, const ShadowMaps& maps, glm::vec4* pixels)
      : frame_(frame), maps_(maps), pixels_(pixels) {}

  // Queues the pixel at pixels[offset]: world position P, the interpolated
  // normal (normalized here, and negated for a back face, as the scalar path
  // does), O_d, the material and the pixel's k_e (the material's, or k_e·E
  // with an emissive texture) and its eye depth d (fog); shades when four are queued.
  void add(std::size_t offset, glm::vec3 P, glm::vec3 interpolatedNormal, bool back, glm::vec3 baseColor, const CourseMaterial& material,
           glm::vec3 emissive, float depth) {
    const int k = count_++;
    offset_[k] = offset;
    D_[k] = depth;
    for (int c = 0; c < 3; ++c) {
      P_[c][k] = P[c];
      N_[c][k] = interpolatedNormal[c];
      O_[c][k] = baseColor[c];
      E_[c][k] = emissive[c];
    }
    back_[k] = back ? 1.0f : 0.0f;  // a back face: N is negated
    material_[k] = &material;
    if (count_ == kLanes) flush();
  }

#if defined(__SSE2__)
  // add() for the four pixels pixels[offset .. offset+3] of one triangle, as lanes; frames without fog only.
  void add4(std::size_t offset, const __m128 (&P)[3], const __m128 (&interpolatedNormal)[3], bool back, glm::vec3 baseColor,
            const CourseMaterial& material) {
    if (count_ != 0) {
      alignas(16) float p[3][4], n[3][4];
      for (int c = 0; c < 3; ++c) _mm_store_ps(p[c], P[c]), _mm_store_ps(n[c], interpolatedNormal[c]);
      for (int k = 0; k < 4; ++k)
        add(offset + static_cast<std::size_t>(k), {p[0][k], p[1][k], p[2][k]}, {n[0][k], n[1][k], n[2][k]}, back, baseColor, material, material.emissive,
            0.0f);
      return;
    }
    for (int k = 0; k < 4; ++k) offset_[k] = offset + static_cast<std::size_t>(k), material_[k] = &material, back_[k] = back ? 1.0f : 0.0f;
    for (int c = 0; c < 3; ++c) {
      _mm_store_ps(P_[c], P[c]);
      _mm_store_ps(N_[c], interpolatedNormal[c]);
      _mm_store_ps(O_[c], _mm_set1_ps(baseColor[c]));
      _mm_store_ps(E_[c], _mm_set1_ps(material.emissive[c]));
    }
    count_ = 4;
    flush();
  }
#endif

  // Shades what is queued.
  void flush();

 private:
  const FrameInputs& frame_;
  const ShadowMaps& maps_;
  glm::vec4* pixels_;  // the colour buffer, linear RGBA
  int count_ = 0;
  std::size_t offset_[kLanes];
  const CourseMaterial* material_[kLanes];
  alignas(16) float P_[3][kLanes], N_[3][kLanes], O_[3][kLanes], E_[3][kLanes], D_[kLanes], back_[kLanes];
  alignas(16) float ka_[kLanes], kd_[kLanes], ks_[kLanes], n_[kLanes], m_[kLanes];  // filled by flush
};

}  // namespace facet::cpu
