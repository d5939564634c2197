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

// Why eyeMatrix(eye, reference, up) is not defined, or nullptr when it is:
// distinct points whose distance a float holds, up not zero and not (nearly)
// parallel to the line of sight.
const char* eyeFrameProblem(glm::vec3 eye, glm::vec3 reference, glm::vec3 up);
inline bool eyeFrameIsValid(glm::vec3 eye, glm::vec3 reference, glm::vec3 up) { return eyeFrameProblem(eye, reference, up) == nullptr; }

}  // namespace facet
