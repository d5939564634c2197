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
  queueRunLanes<Float16>(in, px, py, offset, back, baseColor, material, alpha, lanes, offsets, at);
}

}  // namespace facet::cpu
