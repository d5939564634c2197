// The sixteen-lane Phong batch: the only translation unit built with
// -mavx512f (renderer/cpu/CMakeLists.txt). As for phong_batch_avx2.cpp, no
// function here may leave an out-of-line copy another translation unit also
// defines (an AVX-512 copy would run on CPUs without it): the entry point is
// flattened, and tests/cpu/wide_symbols.cmake holds it.
#include "cpu/phong_batch.h"

#if !defined(__AVX512F__)
#error "phong_batch_avx512.cpp is built with -mavx512f"
#endif

namespace facet::cpu {

__attribute__((flatten)) void shadeSixteenLanes(const FrameInputs& frame, const ShadowMaps& maps, const PhongLanes& in, float* rgba,
                                                const std::size_t* offsets, int count, const BlendOver* over) {
  if (count > 16) shadeLanes<Twice<Float16>>(frame, maps, in, 0, rgba, offsets, count, over);
  else shadeLanes<Float16>(frame, maps, in, 0, rgba, offsets, count, over);
}

__attribute__((flatten)) void queueSixteenLanes(const Interpolation& in, int px, int py, std::size_t offset, bool back, glm::vec3 baseColor,
                                                const CourseMaterial& material, const float* alpha, PhongLanes& lanes, std::size_t* offsets, int at) {
  const __m512 x = _mm512_add_ps(_mm512_set1_ps(static_cast<float>(px)),
                                 _mm512_setr_ps(0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f, 8.0f, 9.0f, 10.0f, 11.0f, 12.0f, 13.0f, 14.0f, 15.0f));
  const __m512 y = _mm512_set1_ps(static_cast<float>(py));
  const auto planeAt = [&](const Plane& p) { return _mm512_fmadd_ps(_mm512_set1_ps(p.dady), y, _mm512_fmadd_ps(_mm512_set1_ps(p.dadx), x, _mm512_set1_ps(p.a0))); };
  const __m512 w = _mm512_div_ps(_mm512_set1_ps(1.0f), planeAt(in.oneOverWPlane()));
  const auto put = [&](float* column, __m512 v) { _mm512_storeu_ps(column + at, v); };
  for (int c = 0; c < 3; ++c) {
    put(lanes.P[c], _mm512_mul_ps(planeAt(in.varyingPlane(c)), w));
    put(lanes.N[c], _mm512_mul_ps(planeAt(in.varyingPlane(3 + c)), w));
    put(lanes.O[c], _mm512_set1_ps(baseColor[c]));
    put(lanes.E[c], _mm512_set1_ps(material.emissive[c]));
  }
  put(lanes.alpha, alpha ? _mm512_loadu_ps(alpha) : _mm512_set1_ps(1.0f));
  put(lanes.back, _mm512_set1_ps(back ? 1.0f : 0.0f));
  put(lanes.ka, _mm512_set1_ps(material.ka));
  put(lanes.kd, _mm512_set1_ps(material.kd));
  put(lanes.ks, _mm512_set1_ps(material.ks));
  put(lanes.n, _mm512_set1_ps(material.shininess));
  put(lanes.m, _mm512_set1_ps(material.metallic));
  const __m512i first = _mm512_add_epi64(_mm512_set1_epi64(static_cast<long long>(offset)), _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7));
  _mm512_storeu_si512(offsets + at, first);
  _mm512_storeu_si512(offsets + at + 8, _mm512_add_epi64(first, _mm512_set1_epi64(8)));
}

}  // namespace facet::cpu
