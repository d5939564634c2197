#include "common/lane_width.h"

#include <string>

#include "common/error.h"

namespace facet {

int widestLanes() {
#if defined(FACET_AVX512_LANES)
  if (__builtin_cpu_supports("avx512f")) return 16;  // as for AVX2: and the OS saves the 512-bit registers and masks
#endif
#if defined(FACET_AVX2_LANES)
  if (__builtin_cpu_supports("avx2")) return 8;  // libgcc also checks that the OS saves the 256-bit registers
#endif
#if defined(__SSE2__)
  return 4;
#else
  return 1;
#endif
}

void checkLanes(int lanes) {
  if (lanes != 1 && lanes != 4 && lanes != 8 && lanes != 16) throw Error("cpu: " + std::to_string(lanes) + " lanes (1, 4, 8 or 16)");
  if (lanes > widestLanes()) throw Error("cpu: " + std::to_string(lanes) + " lanes, this CPU runs at most " + std::to_string(widestLanes()));
}

}  // namespace facet
