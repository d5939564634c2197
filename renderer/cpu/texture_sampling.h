#pragma once
// Base colour texture lookup (renderer/PIPELINE.md, section 8).
// Mirror: shaders/texture.glsl — same functions, same order.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "image/image.h"

namespace facet::cpu {

// REPEAT: i mod size in [0, size), with % only on non-negative operands.
inline int wrap(int i, int size) { return i >= 0 ? i % size : size - 1 - (-1 - i) % size; }

// a + t·(b - a), written out on both sides (GLSL's mix may round as a·(1 - t) + b·t).
glm::vec3 lerp(glm::vec3 a, glm::vec3 b, float t);

// Bilinear from four texels, REPEAT wrap, no mipmaps; t = 0 is the top of the
// glTF image and facet::Image stores the bottom row first.
glm::vec3 sampleBaseColor(const Image& image, glm::vec2 st);

}  // namespace facet::cpu
