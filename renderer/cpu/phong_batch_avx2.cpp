// The eight-lane Phong batch: the only translation unit built with -mavx2
// (renderer/cpu/CMakeLists.txt). Nothing here may leave an out-of-line copy
// of a function other translation units also define: the linker keeps one
// copy of such a function for the whole program, and an AVX2 copy would run
// on CPUs without AVX2. So the entry point is flattened (every call in it
// inlined), and tests/cpu/wide_symbols.cmake fails when this object defines any
// symbol but its own and the eight-lane types' instances.
#include "cpu/phong_batch.h"

#if !defined(__AVX2__)
#error "phong_batch_avx2.cpp is built with -mavx2"
#endif

namespace facet::cpu {

__attribute__((flatten)) void shadeEightLanes(const FrameInputs& frame, const ShadowMaps& maps, const PhongLanes& in, float* rgba,
                                              const std::size_t* offsets, int count, const BlendOver* over) {
  if (count > 8) shadeLanes<Twice<Float8>>(frame, maps, in, 0, rgba, offsets, count, over);
  else shadeLanes<Float8>(frame, maps, in, 0, rgba, offsets, count, over);
}

__attribute__((flatten)) void queueEightLanes(const Interpolation& in, int px, int py, std::size_t offset, bool back, glm::vec3 baseColor,
                                              const CourseMaterial& material, const float* alpha, PhongLanes& lanes, std::size_t* offsets, int at) {
  const __m256 x = _mm256_add_ps(_mm256_set1_ps(static_cast<float>(px)), _mm256_setr_ps(0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f));
  const __m256 y = _mm256_set1_ps(static_cast<float>(py));
  // fusedMultiplyAdd per lane: the instruction where the build has FMA, else the C library's exact one.
  const auto fused = [](__m256 a, __m256 b, __m256 c) {
#if defined(__FMA__)
    return _mm256_fmadd_ps(a, b, c);
#else
    alignas(32) float u[8], v[8], w[8];
    _mm256_store_ps(u, a), _mm256_store_ps(v, b), _mm256_store_ps(w, c);
    for (int k = 0; k < 8; ++k) u[k] = fusedMultiplyAdd(u[k], v[k], w[k]);
    return _mm256_load_ps(u);
#endif
  };
  const auto planeAt = [&](const Plane& p) { return fused(_mm256_set1_ps(p.dady), y, fused(_mm256_set1_ps(p.dadx), x, _mm256_set1_ps(p.a0))); };
  const __m256 w = _mm256_div_ps(_mm256_set1_ps(1.0f), planeAt(in.oneOverWPlane()));
  const auto put = [&](float* column, __m256 v) { _mm256_storeu_ps(column + at, v); };
  for (int c = 0; c < 3; ++c) {
    put(lanes.P[c], _mm256_mul_ps(planeAt(in.varyingPlane(c)), w));
    put(lanes.N[c], _mm256_mul_ps(planeAt(in.varyingPlane(3 + c)), w));
    put(lanes.O[c], _mm256_set1_ps(baseColor[c]));
    put(lanes.E[c], _mm256_set1_ps(material.emissive[c]));
  }
  put(lanes.alpha, alpha ? _mm256_loadu_ps(alpha) : _mm256_set1_ps(1.0f));
  put(lanes.back, _mm256_set1_ps(back ? 1.0f : 0.0f));
  put(lanes.ka, _mm256_set1_ps(material.ka));
  put(lanes.kd, _mm256_set1_ps(material.kd));
  put(lanes.ks, _mm256_set1_ps(material.ks));
  put(lanes.n, _mm256_set1_ps(material.shininess));
  put(lanes.m, _mm256_set1_ps(material.metallic));
  const __m256i first = _mm256_add_epi64(_mm256_set1_epi64x(static_cast<long long>(offset)), _mm256_setr_epi64x(0, 1, 2, 3));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(offsets + at), first);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(offsets + at + 4), _mm256_add_epi64(first, _mm256_set1_epi64x(4)));
}

}  // namespace facet::cpu
