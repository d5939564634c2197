#pragma once
// Phong shading's per-pixel illumination four or eight pixels at a time: the
// lanes of lighting.h's illuminate<Float4> (SSE2), illuminate<Float8>
// (AVX2) or illuminate<Float16> (AVX-512F), the widest the CPU has, shade and viewVector, the same code as one
// pixel's illuminate<float> (lanes.h: every operation the same IEEE
// operation per lane), so the result is bit-identical to shading each pixel
// alone whatever the width; tests/cpu/test_fast_paths.cpp holds every width
// against it. At 8 and 16 lanes a batch queues twice the width and shades
// it as two interleaved halves (lane_pairs.h).
// Pixels of different triangles and materials share a batch.
// Without SSE2 the batch shades its pixels one by one.
#include <algorithm>
#include <cstdint>

#include "shading/blending.h"
#include "common/lane_width.h"
#include "shading/lighting.h"
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
void queueEightLanes(const Interpolation& in, int px, int py, std::size_t offset, bool back, glm::vec3 baseColor,
                     const CourseMaterial& material, const float* alpha, PhongLanes& lanes, std::size_t* offsets, int at);
#endif
#if defined(FACET_AVX512_LANES)
// queueRunLanes<Float16>: sixteen, at lanes [at, at + 16); only where widestLanes() is 16 (phong_batch_avx512.cpp).
void queueSixteenLanes(const Interpolation& in, int px, int py, std::size_t offset, bool back, glm::vec3 baseColor,
                       const CourseMaterial& material, const float* alpha, PhongLanes& lanes, std::size_t* offsets, int at);
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

  // The n pixels pixels[offset .. offset+n-1] of one triangle, n from 1 to
  // the batch's lanes, interpolated on the narrowest of 4, 8 and 16 lanes
  // that holds them (queueRunLanes, phong_lanes.h: four here, eight and
  // sixteen in queueEightLanes and queueSixteenLanes) straight into the
  // queue wherever it stands, with α from alpha[0..n-1] (null: 1); frames
  // without fog only. A run the queue has no room for is split where the
  // batch is shaded. A batch of one lane queues each pixel as add does.
  void addRun(int n, std::size_t offset, const Interpolation& in, int px, int py, bool back, glm::vec3 baseColor, const CourseMaterial& material,
              const float* alpha) {
    if (lanes_ < 4) {
      for (int k = 0; k < n; ++k) {
        const float w = in.inverseWAt(px + k, py);
        add(offset + static_cast<std::size_t>(k), in.varying3At(0, px + k, py, w), in.varying3At(3, px + k, py, w), back, baseColor, material,
            material.emissive, 0.0f, alpha ? alpha[k] : 1.0f);
      }
      return;
    }
    while (n > 0) {
      const int m = std::min(n, capacity_ - count_);
#if defined(__SSE2__)
      if (m <= 4) queueRunLanes<Float4>(in, px, py, offset, back, baseColor, material, alpha, in_, offset_, count_);  // inline: most runs
      else
#endif
        queueRun(m, offset, in, px, py, back, baseColor, material, alpha);
      count_ += m;
      if (count_ == capacity_) flush();
      n -= m, px += m, offset += static_cast<std::size_t>(m);
      if (alpha) alpha += m;
    }
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
  std::size_t offset_[PhongLanes::kColumn];  // as a column: room for a run's store past the queue
  PhongLanes in_;

  // n pixels of addRun's at lanes [count_, count_ + n), n ≤ capacity_ - count_, more than four (phong_batch.cpp).
  void queueRun(int n, std::size_t offset, const Interpolation& in, int px, int py, bool back, glm::vec3 baseColor, const CourseMaterial& material,
                const float* alpha);
};

}  // namespace facet::cpu
