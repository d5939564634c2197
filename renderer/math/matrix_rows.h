#pragma once
// The course writes matrices row by row; GLM stores them column by column.
// fromRows lets the code read like the course notes.
#include <glm/mat4x4.hpp>

namespace facet {

// Builds a 4x4 matrix from its 16 entries given row by row (r<row><col>).
constexpr glm::mat4 fromRows(float r00, float r01, float r02, float r03,
                             float r10, float r11, float r12, float r13,
                             float r20, float r21, float r22, float r23,
                             float r30, float r31, float r32, float r33) {
  return glm::mat4(r00, r10, r20, r30,   // column 0
                   r01, r11, r21, r31,   // column 1
                   r02, r12, r22, r32,   // column 2
                   r03, r13, r23, r33);  // column 3
}

}  // namespace facet
