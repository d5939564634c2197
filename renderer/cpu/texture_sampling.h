#pragma once
// Base colour texture lookup (renderer/PIPELINE.md, section 8).
// Mirror: shaders/texture.glsl — same functions, same order.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "image/image.h"

namespace facet::cpu {

// IEC 61966-2-1 inverse: an sRGB-encoded value in [0,1] to linear.
glm::vec3 decodeSrgb(glm::vec3 c);

// a + t·(b - a), as GLSL's mix computes it on llvmpipe (glm::mix computes
// a·(1 - t) + b·t, which rounds differently).
glm::vec3 lerp(glm::vec3 a, glm::vec3 b, float t);

// Bilinear from four texels, REPEAT wrap, no mipmaps; t = 0 is the top of the
// glTF image and facet::Image stores the bottom row first.
glm::vec3 sampleBaseColor(const Image& image, glm::vec2 st);

}  // namespace facet::cpu
