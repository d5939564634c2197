#pragma once
// SplitMix64 (Steele, Lea and Flood 2014): facet's one generator of seeded
// random numbers, for anti-aliasing's jitter (pipeline/antialiasing.cpp),
// each particle's start (particles/particle_system.cpp) and the ray
// tracer's paths (ray/sampling.h). A fixed, portable sequence from a seed,
// so that an image depends on its seed alone. Defined here, in the header,
// because the ray tracer draws from it in its innermost loop.
#include <cstdint>

namespace facet {

// SplitMix64's output function: every input bit flips about half of the
// output bits. It also hashes seeds into starting states.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

class SplitMix64 {
 public:
  explicit constexpr SplitMix64(std::uint64_t state) : state_(state) {}

  // The state steps by 2^64/φ (odd, so every state comes once in 2^64 steps) and is mixed.
  constexpr std::uint64_t next() { return mix64(state_ += 0x9E3779B97F4A7C15ull); }
  // A number in [0, 1): the top 24 bits over 2^24, exact in float (and in double).
  constexpr float unitFloat() { return static_cast<float>(next() >> 40) * 0x1p-24f; }
  // A number in [0, 1): the top 53 bits over 2^53, exact in double.
  constexpr double unitDouble() { return static_cast<double>(next() >> 11) * 0x1p-53; }

 private:
  std::uint64_t state_;
};

}  // namespace facet
