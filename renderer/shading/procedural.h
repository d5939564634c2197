#pragma once
// Procedural textures (renderer/PIPELINE.md, "Textures"): a checker and four
// octaves of value noise of the model-space point, in the operations of
// PIPELINE.md, "Arithmetic" (integer hashing modulo 2^32, +, -, ·, /, floor).
// Mirror: shaders/procedural.glsl — same functions, same order.
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

#include "settings/render_settings.h"

namespace facet {

// floor(x) as an integer, clamped to ±2^24 first (as texel indices are).
inline int latticeIndex(float floored) { return static_cast<int>(floored < -16777216.0f ? -16777216.0f : (floored > 16777216.0f ? 16777216.0f : floored)); }

// The lattice value at integer corner (x, y, z), in [0, 1).
inline float latticeValue(int x, int y, int z) {
  std::uint32_t h = (static_cast<std::uint32_t>(x) * 73856093u) ^ (static_cast<std::uint32_t>(y) * 19349663u) ^ (static_cast<std::uint32_t>(z) * 83492791u);
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

inline float mixScalar(float a, float b, float t) { return a + t * (b - a); }

// Value noise v(q) in [0, 1).
inline float valueNoise(glm::vec3 q) {
  const float fx = std::floor(q.x), fy = std::floor(q.y), fz = std::floor(q.z);
  const int x = latticeIndex(fx), y = latticeIndex(fy), z = latticeIndex(fz);
  const float tx = q.x - fx, ty = q.y - fy, tz = q.z - fz;
  const float ux = tx * tx * (3.0f - 2.0f * tx), uy = ty * ty * (3.0f - 2.0f * ty), uz = tz * tz * (3.0f - 2.0f * tz);
  const float x00 = mixScalar(latticeValue(x, y, z), latticeValue(x + 1, y, z), ux);
  const float x10 = mixScalar(latticeValue(x, y + 1, z), latticeValue(x + 1, y + 1, z), ux);
  const float x01 = mixScalar(latticeValue(x, y, z + 1), latticeValue(x + 1, y, z + 1), ux);
  const float x11 = mixScalar(latticeValue(x, y + 1, z + 1), latticeValue(x + 1, y + 1, z + 1), ux);
  return mixScalar(mixScalar(x00, x10, uy), mixScalar(x01, x11, uy), uz);
}

// The pattern's grey at model-space point P scaled by k.
inline float proceduralGrey(Procedural pattern, glm::vec3 P, float k) {
  const glm::vec3 p = P * k;
  if (pattern == Procedural::Checker) {
    const int c = latticeIndex(std::floor(p.x)) + latticeIndex(std::floor(p.y)) + latticeIndex(std::floor(p.z));
    return (c & 1) == 0 ? 1.0f : 0.05f;
  }
  const float sum = ((valueNoise(p) + 0.5f * valueNoise(2.0f * p)) + 0.25f * valueNoise(4.0f * p)) + 0.125f * valueNoise(8.0f * p);
  return sum / 1.875f;
}

}  // namespace facet
