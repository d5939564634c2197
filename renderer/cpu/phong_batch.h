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
#include "cpu/lane_width.h"
#include "cpu/lighting.h"
#include "cpu/phong_lanes.h"
#include "image/color_buffer.h"

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

  // The n = 4, 8 or 16 pixels pixels[offset .. offset+n-1] of one triangle,
  // interpolated on n lanes (queueRunLanes, phong_lanes.h: four here, eight
  // and sixteen in queueEightLanes and queueSixteenLanes), with α from
  // alpha[0..n-1] (null: 1); frames without fog only. Four where the batch
  // shades four lanes or more, eight or sixteen where it shades that many;
  // and only where its queue is on an n-lane column. Elsewhere false, and
  // nothing queued.
  bool addRun(int n, std::size_t offset, const Interpolation& in, int px, int py, bool back, glm::vec3 baseColor, const CourseMaterial& material,
              const float* alpha) {
#if defined(__SSE2__)
    if (n == 4) {
      if (lanes_ < 4 || count_ % 4 != 0) return false;
      queueRunLanes<Float4>(in, px, py, offset, back, baseColor, material, alpha, in_, offset_, count_);
      count_ += 4;
      if (count_ == capacity_) flush();
      return true;
    }
#endif
    return addWideRun(n, offset, in, px, py, back, baseColor, material, alpha);
  }

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

  // addRun's eight or sixteen: phong_batch.cpp, built where the wide paths are.
  bool addWideRun(int n, std::size_t offset, const Interpolation& in, int px, int py, bool back, glm::vec3 baseColor, const CourseMaterial& material,
                  const float* alpha);
};

}  // namespace facet::cpu
