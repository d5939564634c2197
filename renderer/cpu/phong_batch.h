#pragma once
// Phong shading's per-pixel illumination four or eight pixels at a time: the
// lanes of lighting.h's illuminate<Float4> (SSE2), illuminate<Float8>
// (AVX2) or illuminate<Float16> (AVX-512F), the widest the CPU has, shade and viewVector, the same code as one
// pixel's illuminate<float> (lanes.h: every operation the same IEEE
// operation per lane), so the result is bit-identical to shading each pixel
// alone whatever the width; tests/cpu/test_fast_paths.cpp holds every width
// against it. At 8 and 16 lanes a batch queues twice the width and shades
// it as two interleaved halves (lane_pairs.h; README, "Two batches side by side").
// Pixels of different triangles and materials share a batch.
// Without SSE2 the batch shades its pixels one by one.
#include <cstdint>

#include "cpu/blending.h"
#include "cpu/interpolation.h"
#include "cpu/lane_width.h"
#include "cpu/lighting.h"
#include "cpu/phong_lanes.h"
#include "image/color_buffer.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace facet::cpu {

#if defined(FACET_AVX2_LANES)
// shadeLanes<Float8>, or <Twice<Float8>> for count > 8 (phong_lanes.h); call only where widestLanes() is 8 or more
// (phong_batch_avx2.cpp, built for AVX2).
void shadeEightLanes(const FrameInputs& frame, const ShadowMaps& maps, const PhongLanes& in, float* rgba, const std::size_t* offsets, int count,
                     const BlendOver* over);
#endif
#if defined(FACET_AVX512_LANES)
// shadeLanes<Float16>, or <Twice<Float16>> for count > 16; call only where widestLanes() is 16 (phong_batch_avx512.cpp,
// built for AVX-512F).
void shadeSixteenLanes(const FrameInputs& frame, const ShadowMaps& maps, const PhongLanes& in, float* rgba, const std::size_t* offsets, int count,
                     const BlendOver* over);
#endif

#if defined(FACET_AVX2_LANES)
// queueRunLanes<Float8> (phong_lanes.h): eight pixels of one triangle queued at lanes [at, at + 8);
// call only where widestLanes() is 8 or more (phong_batch_avx2.cpp).
void queueEightLanes(const Interpolation& in, int px, int py, std::size_t offset, bool back, glm::vec3 baseColor, const CourseMaterial& material,
                     const float* alpha, PhongLanes& lanes, std::size_t* offsets, int at);
#endif
#if defined(FACET_AVX512_LANES)
// queueRunLanes<Float16>: sixteen, at lanes [at, at + 16); only where widestLanes() is 16 (phong_batch_avx512.cpp).
void queueSixteenLanes(const Interpolation& in, int px, int py, std::size_t offset, bool back, glm::vec3 baseColor, const CourseMaterial& material,
                       const float* alpha, PhongLanes& lanes, std::size_t* offsets, int at);
#endif

class PhongBatch {
 public:
  // lanes: 16, 8, 4 or 1, at most widestLanes(). With `over`, each pixel
  // blends over what `pixels` holds with the α it was queued with, else it is written opaque.
  PhongBatch(const FrameInputs& frame, const ShadowMaps& maps, glm::vec4* pixels, int lanes, const BlendOver* over = nullptr);

  // Queues the pixel at pixels[offset]: world position P, the interpolated
  // normal (normalized here, and negated for a back face, as the scalar path
  // does), O_d, the material and the pixel's k_e (the material's, or k_e·E
  // with an emissive texture), its eye depth d (fog) and α (a blended pass);
  // shades when the batch is full.
  void add(std::size_t offset, glm::vec3 P, glm::vec3 interpolatedNormal, bool back, glm::vec3 baseColor, const CourseMaterial& material,
           glm::vec3 emissive, float depth, float alpha = 1.0f) {
    const int k = count_++;
    offset_[k] = offset;
    in_.D[k] = depth;
    in_.alpha[k] = alpha;
    for (int c = 0; c < 3; ++c) {
      in_.P[c][k] = P[c];
      in_.N[c][k] = interpolatedNormal[c];
      in_.O[c][k] = baseColor[c];
      in_.E[c][k] = emissive[c];
    }
    in_.back[k] = back ? 1.0f : 0.0f;  // a back face: N is negated
    in_.ka[k] = material.ka, in_.kd[k] = material.kd, in_.ks[k] = material.ks, in_.n[k] = material.shininess, in_.m[k] = material.metallic;
    if (count_ == capacity_) flush();
  }

#if defined(__SSE2__)
  // add() for the four pixels pixels[offset .. offset+3] of one triangle, as lanes; frames without fog only.
  __attribute__((always_inline)) void add4(std::size_t offset, const __m128 (&P)[3], const __m128 (&interpolatedNormal)[3], bool back,
                                           glm::vec3 baseColor, const CourseMaterial& material, __m128 alpha) {
    const int at = count_;
    if (at % 4 != 0 || lanes_ < 4) {  // not on a four-lane column: one pixel at a time
      alignas(16) float p[3][4], n[3][4], a[4];
      for (int c = 0; c < 3; ++c) _mm_store_ps(p[c], P[c]), _mm_store_ps(n[c], interpolatedNormal[c]);
      _mm_store_ps(a, alpha);
      for (int k = 0; k < 4; ++k)
        add(offset + static_cast<std::size_t>(k), {p[0][k], p[1][k], p[2][k]}, {n[0][k], n[1][k], n[2][k]}, back, baseColor, material, material.emissive,
            0.0f, a[k]);
      return;
    }
    for (int k = 0; k < 4; ++k) offset_[at + k] = offset + static_cast<std::size_t>(k);
    _mm_store_ps(in_.alpha + at, alpha);
    _mm_store_ps(in_.back + at, _mm_set1_ps(back ? 1.0f : 0.0f));
    _mm_store_ps(in_.ka + at, _mm_set1_ps(material.ka));
    _mm_store_ps(in_.kd + at, _mm_set1_ps(material.kd));
    _mm_store_ps(in_.ks + at, _mm_set1_ps(material.ks));
    _mm_store_ps(in_.n + at, _mm_set1_ps(material.shininess));
    _mm_store_ps(in_.m + at, _mm_set1_ps(material.metallic));
    for (int c = 0; c < 3; ++c) {
      _mm_store_ps(in_.P[c] + at, P[c]);
      _mm_store_ps(in_.N[c] + at, interpolatedNormal[c]);
      _mm_store_ps(in_.O[c] + at, _mm_set1_ps(baseColor[c]));
      _mm_store_ps(in_.E[c] + at, _mm_set1_ps(material.emissive[c]));
    }
    count_ += 4;
    if (count_ == capacity_) flush();
  }
#endif

  // add4 for the n = 8 or 16 pixels pixels[offset .. offset+n-1] of one
  // triangle, interpolated on n lanes (queueEightLanes, queueSixteenLanes),
  // with α from alpha[0..n-1] (null: 1); frames without fog only. Only where
  // the batch shades n lanes and its queue is on an n-lane column; false, and
  // nothing queued, elsewhere.
  bool addRun(int n, std::size_t offset, const Interpolation& in, int px, int py, bool back, glm::vec3 baseColor, const CourseMaterial& material,
              const float* alpha);  // phong_batch.cpp, built where the wide paths are

  // Shades what is queued.
  void flush();

 private:
  const FrameInputs& frame_;
  const ShadowMaps& maps_;
  glm::vec4* pixels_;  // the colour buffer, linear RGBA
  const BlendOver* over_;
  int lanes_;
  int capacity_;  // pixels queued before they are shaded: twice the lanes at 16 (lane_pairs.h)
  int count_ = 0;
  std::size_t offset_[PhongLanes::kMost];
  PhongLanes in_;
};

}  // namespace facet::cpu
