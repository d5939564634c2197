#include "cpu/depth_rows.h"

namespace facet::cpu {

void lessRowOnLanes(int lanes, const Plane& z, int x0, int x1, int py, float* depth, std::uint32_t* ids, std::uint32_t id) {
#if defined(FACET_AVX512_LANES)
  if (lanes == 16) return lessRowSixteen(z, x0, x1, py, depth, ids, id);
#endif
  (void)lanes;
  lessRow(z, x0, x1, py, depth, ids, id);
}

TakenRun frontRowOnLanes(int lanes, const Plane& z, int x0, int x1, int py, const float* depth, std::uint32_t* ids, std::uint32_t id) {
#if defined(FACET_AVX512_LANES)
  if (lanes == 16) return frontRowSixteen(z, x0, x1, py, depth, ids, id);
#endif
  (void)lanes;
  return frontRow(z, x0, x1, py, depth, ids, id);
}

}  // namespace facet::cpu
