#pragma once
// Memory counted before it is allocated, so that a small file cannot make
// facet take gigabytes: an accessor's count, an image header's size, a
// node that places a mesh once more, a light's shadow-map faces are all
// priced first and refused with one line naming the object and the budget.
// The budgets themselves are limits of render_settings.h
// (kSceneMemoryBudget, kFrameMemoryBudget).
#include <cstdint>
#include <string>

namespace facet {

// Bytes for a message: "1 GiB" and "512 MiB" for whole binary units (the
// budgets), else decimal with three figures: "805 MB", "1.61 GB", "12.3 kB".
std::string byteCount(std::uint64_t bytes);

// A running total against a limit. charge() adds what an object needs, or
// throws facet::Error when that would pass the limit, before the caller
// allocates anything:
//   "accessors[3]: 67108864 vertices need 1.61 GB, more than the scene budget of 1 GiB"
class MemoryBudget {
 public:
  // `name` says what is budgeted in messages: "scene budget", "frame budget".
  MemoryBudget(std::uint64_t limit, std::string name);

  // `what` names the object and, in the plural, what it holds, so that
  // " need N MB" can follow: "images[2]: 16384x16384 pixels".
  void charge(std::uint64_t bytes, const std::string& what);
  // Whether charge(bytes, ...) would pass, to build its message only when not.
  bool fits(std::uint64_t bytes) const { return bytes <= limit_ && used_ <= limit_ - bytes; }
  std::uint64_t used() const { return used_; }
  std::uint64_t limit() const { return limit_; }

 private:
  std::uint64_t limit_;
  std::uint64_t used_ = 0;
  std::string name_;
};

// What a frame works in for one instance, priced after the larger of the two
// backends, the CPU rasterizer (the GL backend uploads each mesh once and
// draws its instances from it): per vertex its packed window vertex (x, y,
// z, 1/w and up to 23 varyings), clip coordinates, flags and world position
// (137 bytes; cpu/frame_buffers.h checks it); per triangle its binned record
// and tile references.
inline constexpr std::uint64_t kFrameBytesPerVertex = 144;
inline constexpr std::uint64_t kFrameBytesPerTriangle = 96;
std::uint64_t instanceFrameBytes(std::uint64_t vertices, std::uint64_t triangles);

// S×S float depth texels per shadow-map face (both backends store 32-bit depth).
std::uint64_t shadowMapBytes(int mapSize, int faces);

}  // namespace facet
