#include "math/eye_matrix.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "math/transforms.h"

namespace facet {

glm::mat4 mirrorX() { return scaling({-1.0f, 1.0f, 1.0f}); }

glm::mat4 eyeMatrix(glm::vec3 eye, glm::vec3 reference, glm::vec3 up) {
  const glm::vec3 k = glm::normalize(reference - eye);
  const glm::vec3 i = glm::normalize(glm::cross(up, k));
  const glm::vec3 j = glm::cross(k, i);
  return mirrorX() * generalRotation(i, j, k) * translation(-eye);
}

const char* eyeFrameProblem(glm::vec3 eye, glm::vec3 reference, glm::vec3 up) {
  const auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  if (!finite(eye) || !finite(reference) || !finite(up)) return "eye, reference or up is not finite";
  const glm::vec3 sight = reference - eye;
  const float sightLength = glm::length(sight);
  const float upLength = glm::length(up);
  // |v|² overflows a float past about 1.8e19: k could not be normalized.
  if (!std::isfinite(sightLength)) return "the eye is too far from the reference point for float arithmetic, more than about 1.8e19";
  if (!std::isfinite(upLength)) return "up is too long for float arithmetic, more than about 1.8e19";
  if (!(sightLength > 0.0f)) return "the eye is on the reference point";
  if (!(upLength > 0.0f)) return "up is zero";
  // sin of the angle between up and the line of sight must not vanish.
  const float sine = glm::length(glm::cross(up / upLength, sight / sightLength));
  return sine > 1e-4f ? nullptr : "up is along the line of sight";
}

}  // namespace facet
