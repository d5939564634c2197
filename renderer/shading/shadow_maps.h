#pragma once
// Pass 1's output on the CPU: one S×S float depth map per light face, stored
// as layers of one array, as the GL backend stores them in a 2D array texture.
// The renderer keeps the maps from frame to frame; the shadow pass clears
// only the tiles that the last frame or this one drew into, and every tile
// of freshly allocated maps (on its threads, where the pages are first touched).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/large_pages.h"

namespace facet {

struct ShadowMaps {
  int size = 0;                // S
  int layers = 0;
  LargeVector<float> depth;    // layer-major, then rows bottom first; 1 where nothing was drawn
  std::vector<std::uint8_t> dirty;  // per layer and tile: drawn into since the last clear, or never cleared

  // Maps of S and the layer count, allocated when either changed. Then every
  // tile is dirty and its texels undefined until the shadow pass, which
  // clears each tile to 1 (dirtyTiles says which); a reader that draws no
  // pass sets the texels itself.
  void reset(int s, int layerCount);
  // Layer l's first texel; the layer's rows follow, S texels each.
  float* layer(int l) { return depth.data() + texelIndex(l, 0, 0); }
  const float* layer(int l) const { return depth.data() + texelIndex(l, 0, 0); }
  // The dirty flags of layer l's tiles of tileSize² texels, row-major; all set after an allocation.
  std::uint8_t* dirtyTiles(int l, int tileSize);
  // texelFetch: integer addressing, no filtering.
  float texelFetch(int l, int x, int y) const { return depth[texelIndex(l, x, y)]; }
  // Where texel (x, y) of layer l sits in `depth`.
  std::size_t texelIndex(int l, int x, int y) const {
    return (static_cast<std::size_t>(l) * static_cast<std::size_t>(size) + static_cast<std::size_t>(y)) * static_cast<std::size_t>(size) + static_cast<std::size_t>(x);
  }
};

}  // namespace facet
