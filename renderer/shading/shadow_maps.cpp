#include "shading/shadow_maps.h"

namespace facet {

void ShadowMaps::reset(int s, int layerCount) {
  if (s == size && layerCount == layers && !depth.empty()) return;  // kept: the shadow pass clears what it needs
  size = s;
  layers = layerCount;
  depth.clear();  // no copy of the old texels on growth
  depth.resize(static_cast<std::size_t>(s) * static_cast<std::size_t>(s) * static_cast<std::size_t>(layerCount));  // untouched
  dirty.clear();
}

std::uint8_t* ShadowMaps::dirtyTiles(int l, int tileSize) {
  const std::size_t perLayer = static_cast<std::size_t>((size + tileSize - 1) / tileSize) * static_cast<std::size_t>((size + tileSize - 1) / tileSize);
  if (dirty.size() != perLayer * static_cast<std::size_t>(layers)) dirty.assign(perLayer * static_cast<std::size_t>(layers), 1);  // never cleared
  return dirty.data() + perLayer * static_cast<std::size_t>(l);
}

}  // namespace facet
