#pragma once
// glTF 2.0's sampler enums (5.26 "sampler"): the GL codes a file writes,
// listed once, in the order of facet's enums (scene/scene.h), for the
// document checks that refuse another code and the loader that converts.
#include <array>
#include <optional>

#include "scene/scene.h"

namespace facet {

struct GlEnum {
  int code;
  const char* name;
};

inline constexpr std::array<GlEnum, 2> kMagFilterCodes = {{{9728, "NEAREST"}, {9729, "LINEAR"}}};
inline constexpr std::array<GlEnum, 6> kMinFilterCodes = {{{9728, "NEAREST"},
                                                           {9729, "LINEAR"},
                                                           {9984, "NEAREST_MIPMAP_NEAREST"},
                                                           {9985, "LINEAR_MIPMAP_NEAREST"},
                                                           {9986, "NEAREST_MIPMAP_LINEAR"},
                                                           {9987, "LINEAR_MIPMAP_LINEAR"}}};
inline constexpr std::array<GlEnum, 3> kWrapCodes = {{{10497, "REPEAT"}, {33071, "CLAMP_TO_EDGE"}, {33648, "MIRRORED_REPEAT"}}};

// The position of `code` in `codes`, none when the file wrote another.
template <std::size_t N>
std::optional<int> enumIndex(const std::array<GlEnum, N>& codes, long long code) {
  for (std::size_t i = 0; i < N; ++i)
    if (codes[i].code == code) return static_cast<int>(i);
  return std::nullopt;
}

}  // namespace facet
