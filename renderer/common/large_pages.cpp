#include "common/large_pages.h"

#include <cstdlib>

#include <sys/mman.h>

namespace facet {

void* allocateLarge(std::size_t bytes) {
  if (bytes < kLargePageBytes) return ::operator new(bytes);
  if (bytes > static_cast<std::size_t>(-1) - kLargePageBytes) throw std::bad_alloc();  // the rounding below would wrap
  const std::size_t rounded = (bytes + kLargePageBytes - 1) / kLargePageBytes * kLargePageBytes;  // aligned_alloc's rule
  void* p = std::aligned_alloc(kLargePageBytes, rounded);
  if (p == nullptr) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
  madvise(p, rounded, MADV_HUGEPAGE);  // advice only: refused or ignored, the pages stay 4 KiB
#endif
  return p;
}

void deallocateLarge(void* p, std::size_t bytes) {
  if (bytes < kLargePageBytes) ::operator delete(p);
  else std::free(p);
}

}  // namespace facet
