#pragma once
// llvmpipe runs its vertex and fragment stages with denormals flushed to zero
// (MXCSR FTZ and DAZ; Mesa 22.3 draw_pt.c and lp_rast.c set them around the
// work), so results that would be denormal are 0 and denormal inputs count as
// 0. The CPU backend does the same for every phase of a frame
// (renderer/PIPELINE.md, "Shading"), and puts the caller's mode back after.
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

namespace facet {

class FlushDenormals {
 public:
#if defined(__SSE2__)
  FlushDenormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero); }
  ~FlushDenormals() { _mm_setcsr(saved_); }
#endif
  FlushDenormals(const FlushDenormals&) = delete;
  FlushDenormals& operator=(const FlushDenormals&) = delete;

 private:
#if defined(__SSE2__)
  static constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;
  unsigned saved_;
#endif
};

}  // namespace facet
