#pragma once
// Storage for a frame's large buffers (the CPU's shadow maps and colour
// buffer, the image) on the kernel's 2 MiB pages where it grants them.
// A PCF window reads 2r + 1 rows of a 2048² map, each row 8 KiB from the
// next: on 4 KiB pages every row is another page and another TLB entry, and
// a fresh buffer takes a page fault per 4 KiB. Linux hands an anonymous
// region 2 MiB pages only when asked (transparent_hugepage = madvise, as on
// Debian); elsewhere the request is a no-op and the pages stay small.
#include <cstddef>
#include <new>
#include <utility>
#include <vector>

namespace facet {

// Buffers from this size up are 2 MiB-aligned and advised; smaller ones come from operator new.
inline constexpr std::size_t kLargePageBytes = std::size_t{2} << 20;

void* allocateLarge(std::size_t bytes);            // throws std::bad_alloc
void deallocateLarge(void* p, std::size_t bytes);  // the same `bytes` as allocateLarge's

template <class T>
struct LargePageAllocator {
  using value_type = T;
  LargePageAllocator() = default;
  template <class U>
  LargePageAllocator(const LargePageAllocator<U>&) {}
  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_alloc();
    return static_cast<T*>(allocateLarge(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) { deallocateLarge(p, n * sizeof(T)); }
  // resize(n) default-initializes: new floats are left as the kernel hands
  // them over, untouched, for a user that sets every element itself (the
  // shadow maps clear tile by tile on the pass's threads, ShadowMaps::reset).
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    if constexpr (sizeof...(Args) == 0) ::new (static_cast<void*>(p)) U;
    else ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  friend bool operator==(const LargePageAllocator&, const LargePageAllocator&) { return true; }
};

template <class T>
using LargeVector = std::vector<T, LargePageAllocator<T>>;

}  // namespace facet
