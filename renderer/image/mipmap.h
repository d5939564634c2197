#pragma once
// Mipmaps (renderer/PIPELINE.md, "Textures"): built once per texture, when the
// scene is loaded, and read by both backends, so that no level differs.
#include <cstdint>
#include <vector>

#include "image/image.h"

namespace facet {

// How a texture's bytes are read: colour (base colour, emissive) as sRGB,
// data (metallic-roughness, occlusion) as byte / 255.
enum class TexelEncoding { Srgb, Linear };

// Levels 1, 2, ... of `image` (level 0), down to 1×1: level k+1 is
// max(1, W_k / 2) × max(1, H_k / 2), each texel the box average of the 2×2
// texels above it (3 in a row or column where an odd size leaves one over,
// so every texel of level k counts once). Srgb: colour averaged in linear
// light and re-encoded to sRGB bytes by the contract's encoding; Linear:
// every channel averaged as stored, rounded to the nearest byte. Alpha is
// always averaged as stored.
std::vector<Image> mipLevels(const Image& image, TexelEncoding encoding);

// How many levels mipLevels makes after level 0: floor(log2(max(W, H))).
int mipLevelCount(int width, int height);

// The pixels of a W×H image and all its levels, for pricing before decoding.
std::uint64_t mipChainPixels(int width, int height);

}  // namespace facet
