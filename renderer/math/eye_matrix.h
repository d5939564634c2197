#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace facet {

// Mirror_x: x -> -x. Turns the right-handed frame (i, j, k) into the course's
// left-handed eye space: +x right, +y up, +z forward into the screen.
glm::mat4 mirrorX();

// The course's eye matrix EM = Mirror_x · GRM(i, j, k) · T(-P_eye) with
//   k = (P_ref - P_eye)/|P_ref - P_eye|, i = (v_up × k)/|v_up × k|, j = k × i.
// Maps world space to eye space (eye at the origin, looking along +z).
// The caller ensures P_ref != P_eye and v_up not parallel to k.
glm::mat4 eyeMatrix(glm::vec3 eye, glm::vec3 reference, glm::vec3 up);

// True when eyeMatrix(eye, reference, up) is defined: distinct points, up not
// (nearly) parallel to the line of sight.
bool eyeFrameIsValid(glm::vec3 eye, glm::vec3 reference, glm::vec3 up);

}  // namespace facet
