#include "cpu/phong_batch.h"

#include <cmath>

#include "shading/blending.h"

namespace facet::cpu {

PhongBatch::PhongBatch(const FrameInputs& frame, const ShadowMaps& maps, glm::vec4* pixels, int lanes, const BlendOver* over)
    : frame_(frame), maps_(maps), pixels_(pixels), over_(over), lanes_(lanes), capacity_(lanes >= 8 ? 2 * lanes : lanes) {
  checkLanes(lanes);
}

void PhongBatch::queueRun(int n, std::size_t offset, const Interpolation& in, int px, int py, bool back, glm::vec3 baseColor,
                          const CourseMaterial& material, const float* alpha) {
#if defined(FACET_AVX512_LANES)
  if (n > 8) return queueSixteenLanes(in, px, py, offset, back, baseColor, material, alpha, in_, offset_, count_);
#endif
#if defined(FACET_AVX2_LANES)
  if (n > 4) return queueEightLanes(in, px, py, offset, back, baseColor, material, alpha, in_, offset_, count_);
#endif
  (void)n, (void)offset, (void)in, (void)px, (void)py, (void)back, (void)baseColor, (void)material, (void)alpha;  // four or fewer: addRun's
}

void PhongBatch::flush() {
  if (count_ == 0) return;
  if (lanes_ == 1) {
    const glm::vec3 P{in_.P[0][0], in_.P[1][0], in_.P[2][0]};
    const glm::vec3 N = LitPhongProgram::twoSided<float>({in_.N[0][0], in_.N[1][0], in_.N[2][0]}, in_.back[0] != 0.0f);
    const glm::vec3 O{in_.O[0][0], in_.O[1][0], in_.O[2][0]};
    const glm::vec3 E{in_.E[0][0], in_.E[1][0], in_.E[2][0]};
    const LaneMaterial<float> material{E, in_.ka[0], in_.kd[0], in_.ks[0], in_.n[0], in_.m[0]};
    const glm::vec3 lit = shade(LitPhongProgram::lit<float>(frame_, maps_, material, P, N), O);
    writeFragment(pixels_[offset_[0]], fogged(frame_.fog, lit, in_.D[0]), in_.alpha[0], over_);
    count_ = 0;
    return;
  }
  // The lanes shaded: the narrowest of 4, 8, 16 and 32 that holds the queue (at most the batch's capacity).
  int shaded = 4;
  while (shaded < count_) shaded *= 2;
  for (int k = count_; k < shaded; ++k) {  // unused lanes repeat lane 0; their results are dropped
    for (int c = 0; c < 3; ++c) in_.P[c][k] = in_.P[c][0], in_.N[c][k] = in_.N[c][0], in_.O[c][k] = in_.O[c][0], in_.E[c][k] = in_.E[c][0];
    in_.back[k] = in_.back[0];
    in_.D[k] = in_.D[0];
    in_.alpha[k] = in_.alpha[0];
    in_.ka[k] = in_.ka[0], in_.kd[k] = in_.kd[0], in_.ks[k] = in_.ks[0], in_.n[k] = in_.n[0], in_.m[k] = in_.m[0];
  }
  static_assert(sizeof(glm::vec4) == 4 * sizeof(float));
  float* const rgba = &pixels_[0].x;  // the colour buffer as floats, four a pixel
#if defined(FACET_AVX512_LANES)
  if (lanes_ == 16 && shaded >= 16) shadeSixteenLanes(frame_, maps_, in_, rgba, offset_, count_, over_);  // 16 or twice 16
  else
#endif
#if defined(FACET_AVX2_LANES)
  if (shaded >= 8) shadeEightLanes(frame_, maps_, in_, rgba, offset_, count_, over_);  // 8 or twice 8
  else
#endif
#if defined(__SSE2__)
    for (int first = 0; first < shaded; first += 4) shadeLanes<Float4>(frame_, maps_, in_, first, rgba, offset_, count_, over_);
#endif
  count_ = 0;
}

}  // namespace facet::cpu
