#pragma once
// sRGB (IEC 61966-2-1) as both backends apply it, by table, so that they
// agree to the bit (renderer/PIPELINE.md, "Encoding"):
//
// - A linear value c in [0, 1] is written as the 8-bit level
//   floor(255·E(c) + 0.5), E(c) = 12.92·c for c ≤ 0.0031308, else
//   1.055·c^(1/2.4) - 0.055, evaluated in double precision. Levels never
//   decrease with c, so 255 thresholds decide them: the level of a float c
//   is the number of thresholds t_k (k = 1..255, the smallest float reaching
//   level k) with t_k ≤ c. NaN and c < 0 give 0, c > 1 gives 255.
// - Finding that number: c is clamped to [0, 1] (NaN to 0), then raised to
//   2^-13 (every value below 2^-13 is level 0, as 2^-13 is); its bits >> 15
//   (exponent and top 8 mantissa bits) pick a bucket of 2^15 floats, 256 an
//   octave.
//   No bucket holds more than one threshold (checked when the tables are
//   built), so one entry per bucket decides. It holds the level of the
//   bucket's first float above bit 15 and, below, 2^15 minus where in the
//   bucket the next level begins (the low 15 bits of t_(start+1), or 2^15
//   when that threshold lies beyond the bucket). Adding c's low 15 bits
//   carries into the level exactly when they reach that edge, so the level
//   is (entry + (c's bits & 0x7FFF)) >> 15: one look-up, an add and a
//   shift, the same in both backends (encodeLevel here, shaders/srgb.glsl);
//   levelBySearch is the plain count it is tested against.
// - An 8-bit texel v is decoded to the float nearest the inverse formula at
//   v/255 (v/255 ≤ 0.04045: v/255/12.92, else ((v/255 + 0.055)/1.055)^2.4),
//   in double precision.
//
// The OpenGL backend reads these tables from a uniform block.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "image/image.h"

namespace facet {

// E's constants (IEC 61966-2-1): E(c) = kSrgbSlope·c for c ≤ kSrgbLinearEnd,
// else kSrgbScale·c^(1/kSrgbGamma) - kSrgbOffset.
inline constexpr double kSrgbLinearEnd = 0.0031308, kSrgbSlope = 12.92, kSrgbScale = 1.055, kSrgbOffset = 0.055, kSrgbGamma = 2.4;

inline constexpr int kSrgbBucketShift = 15;
inline constexpr float kSrgbFloor = 0x1p-13f;  // below t_1 = 0.5 / (255·12.92) ≈ 1.52e-4 (checked when the tables are built)
inline constexpr std::uint32_t kSrgbFirstBucket = std::bit_cast<std::uint32_t>(kSrgbFloor) >> kSrgbBucketShift;
inline constexpr std::uint32_t kSrgbBuckets = (std::bit_cast<std::uint32_t>(1.0f) >> kSrgbBucketShift) - kSrgbFirstBucket + 1;  // [2^-13, 1]
inline constexpr std::uint32_t kSrgbInBucket = (1u << kSrgbBucketShift) - 1;  // a float's place in its bucket: its low bits

struct SrgbTables {
  std::array<float, 257> thresholds;               // [k]: the smallest float c with level(c) ≥ k, k = 1..255; [0] = -inf, [256] = +inf
  std::array<float, 256> decoded;                  // [v]: the linear value of 8-bit level v
  std::array<std::uint32_t, kSrgbBuckets> buckets;  // [b - kSrgbFirstBucket]: start << 15 | (2^15 - edge), as described above
};

// Built once, on first use (thread-safe).
const SrgbTables& srgbTables();

// c clamped to [0, 1], NaN to 0 (x86's minps/maxps order: (c < 1 ? c : 1), then (c > 0 ? c : 0)).
inline float clampUnit(float c) { return c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f; }

// The level of a clamped value's `bits` from its bucket's entry.
inline std::uint8_t levelInBucket(std::uint32_t entry, std::uint32_t bits) {
  return static_cast<std::uint8_t>((entry + (bits & kSrgbInBucket)) >> kSrgbBucketShift);
}

// The 8-bit level of linear c by the bucket table.
inline std::uint8_t encodeLevel(float linear) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(std::max(clampUnit(linear), kSrgbFloor));
  return levelInBucket(srgbTables().buckets[(bits >> kSrgbBucketShift) - kSrgbFirstBucket], bits);
}

// The same level as the count of thresholds at or below c, by binary search.
std::uint8_t levelBySearch(float linear);

// Alpha is coverage, not light: stored linearly as floor(255·a + 0.5) of a
// clamped to [0, 1] (NaN to 0), a product and a sum each rounded once, in
// float (shaders/srgb.glsl's alphaLevel computes it `precise`).
inline std::uint8_t alphaLevel(float alpha) { return static_cast<std::uint8_t>(clampUnit(alpha) * 255.0f + 0.5f); }

// The three levels of a linear colour, alpha 255.
inline Rgba8 encodePixel(glm::vec3 linear) { return {encodeLevel(linear.r), encodeLevel(linear.g), encodeLevel(linear.b), 255}; }

// A linear RGBA colour: sRGB levels and the alpha level.
inline Rgba8 encodePixel(glm::vec4 linear) {
  return {encodeLevel(linear.r), encodeLevel(linear.g), encodeLevel(linear.b), alphaLevel(linear.a)};
}

}  // namespace facet
