#pragma once
// Matrix times point in one fixed order, with no fused multiply-add:
//   M·(x, y, z, 1) = ((M[0]·x + M[1]·y) + M[2]·z) + M[3]
// The vertex shader computes gl_Position and world positions the same way
// (`precise`, shaders/transform.glsl), so both backends get bit-identical
// clip coordinates and therefore snap vertices to the same sub-pixel grid.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace facet {

inline glm::vec4 transformPoint(const glm::mat4& m, glm::vec3 p) {
  return ((m[0] * p.x + m[1] * p.y) + m[2] * p.z) + m[3];
}

inline glm::vec3 transformDirection(const glm::mat3& m, glm::vec3 d) {
  return (m[0] * d.x + m[1] * d.y) + m[2] * d.z;
}

}  // namespace facet
