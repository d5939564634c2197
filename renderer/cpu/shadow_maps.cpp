#include "cpu/shadow_maps.h"

namespace facet::cpu {

void ShadowMaps::reset(int s, int layerCount) {
  size = s;
  layers = layerCount;
  depth.assign(static_cast<std::size_t>(s) * static_cast<std::size_t>(s) * static_cast<std::size_t>(layerCount), 1.0f);
}

}  // namespace facet::cpu
