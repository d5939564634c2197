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

bool eyeFrameIsValid(glm::vec3 eye, glm::vec3 reference, glm::vec3 up) {
  const glm::vec3 sight = reference - eye;
  const float sightLength = glm::length(sight);
  const float upLength = glm::length(up);
  if (!(sightLength > 0.0f) || !(upLength > 0.0f) || !std::isfinite(sightLength) || !std::isfinite(upLength))
    return false;
  // sin of the angle between up and the line of sight must not vanish.
  const float sine = glm::length(glm::cross(up / upLength, sight / sightLength));
  return sine > 1e-4f;
}

}  // namespace facet
