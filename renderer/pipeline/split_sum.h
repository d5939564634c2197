#pragma once
// The split-sum factors of shading=pbr's image-based specular light
// (renderer/PIPELINE.md, "Shading"): prefiltered·(F0·A + B), with
// (A, B) = ∫ (1 - x⁵, x⁵)·D·Vis·(N·L) dω over the hemisphere for the BRDF's
// own D and Vis (pipeline/microfacet.h). Built once, in double precision,
// and read by both backends from the same floats.
#include <array>

#include <glm/vec2.hpp>

namespace facet {

inline constexpr int kSplitSumSize = 32;  // N·V columns × roughness rows, at i/31: both ends are entries

struct SplitSumTable {
  std::array<glm::vec2, kSplitSumSize * kSplitSumSize> ab;  // [row·32 + column]: (A, B) at r = row/31, N·V = column/31
};

// The table, computed on first use (1024 Hammersley samples of GGX per entry).
const SplitSumTable& splitSumTable();

}  // namespace facet
