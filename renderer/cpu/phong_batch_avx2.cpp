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
  queueRunLanes<Float8>(in, px, py, offset, back, baseColor, material, alpha, lanes, offsets, at);
}

}  // namespace facet::cpu
