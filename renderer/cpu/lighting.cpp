#include "cpu/lighting.h"

#include <algorithm>
#include <cmath>

namespace facet::cpu {

glm::vec3 encodeSrgb(glm::vec3 linear) {
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) {
    const float c = linear[i] > 0.0f ? std::min(linear[i], 1.0f) : 0.0f;  // NaN -> 0; GLSL leaves clamp(NaN) undefined
    out[i] = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  }
  return out;
}

unsigned char quantize(float encoded) {
  const float c = encoded > 0.0f ? std::min(encoded, 1.0f) : 0.0f;  // NaN -> 0
  return static_cast<unsigned char>(std::floor(c * 255.0f + 0.5f));
}

}  // namespace facet::cpu
