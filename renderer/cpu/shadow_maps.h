#pragma once
// Pass 1's output on the CPU: one S×S float depth map per light face, stored
// as layers of one array, as the GL backend stores them in a 2D array texture.
#include <cstddef>
#include <vector>

namespace facet::cpu {

struct ShadowMaps {
  int size = 0;                // S
  int layers = 0;
  std::vector<float> depth;    // layer-major, then rows bottom first; cleared to 1

  void reset(int s, int layerCount);
  float* layer(int l) { return depth.data() + static_cast<std::size_t>(l) * static_cast<std::size_t>(size) * static_cast<std::size_t>(size); }
  // texelFetch: integer addressing, no filtering.
  float texelFetch(int l, int x, int y) const {
    return depth[(static_cast<std::size_t>(l) * static_cast<std::size_t>(size) + static_cast<std::size_t>(y)) * static_cast<std::size_t>(size) + static_cast<std::size_t>(x)];
  }
};

}  // namespace facet::cpu
