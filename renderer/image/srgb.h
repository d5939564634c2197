#pragma once
// sRGB (IEC 61966-2-1) as both backends apply it, by table, so that they
// agree to the bit (renderer/PIPELINE.md, section 7, "Encoding"):
//
// - A linear value c in [0, 1] is written as the 8-bit level
//   floor(255·E(c) + 0.5), E(c) = 12.92·c for c ≤ 0.0031308, else
//   1.055·c^(1/2.4) - 0.055, evaluated in double precision. Levels never
//   decrease with c, so 255 thresholds decide them: the level of any float c
//   is the number of thresholds t_k (k = 1..255, the smallest float reaching
//   level k) with t_k ≤ c. So NaN and c < 0 give 0, c > 1 gives 255.
// - An 8-bit texel v is decoded to the float nearest the inverse formula at
//   v/255 (v/255 ≤ 0.04045: v/255/12.92, else ((v/255 + 0.055)/1.055)^2.4),
//   in double precision.
//
// The OpenGL backend reads the same two tables from a uniform block
// (shaders/srgb.glsl); the CPU backend finds levels by a faster table built
// from the thresholds (renderer/cpu/srgb_table.h, tested against encodeLevel).
#include <array>
#include <cstdint>

#include <glm/vec3.hpp>

#include "image/image.h"

namespace facet {

struct SrgbTables {
  std::array<float, 256> thresholds;  // [k]: the smallest float c with level(c) ≥ k, k = 1..255; [0] = -inf (unused)
  std::array<float, 256> decoded;     // [v]: the linear value of 8-bit level v
};

// Built once, on first use (thread-safe).
const SrgbTables& srgbTables();

// The level of linear c by binary search over the thresholds, as the shaders do it.
std::uint8_t encodeLevel(float linear);

// The three levels of a linear colour, alpha 255.
Rgba8 encodePixel(glm::vec3 linear);

}  // namespace facet
