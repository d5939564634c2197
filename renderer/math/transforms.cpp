#include "math/transforms.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "math/matrix_rows.h"

namespace facet {

glm::mat4 translation(glm::vec3 t) {
  return fromRows(1, 0, 0, t.x,
                  0, 1, 0, t.y,
                  0, 0, 1, t.z,
                  0, 0, 0, 1);
}

glm::mat4 scaling(glm::vec3 s) {
  return fromRows(s.x, 0, 0, 0,
                  0, s.y, 0, 0,
                  0, 0, s.z, 0,
                  0, 0, 0, 1);
}

glm::mat4 rotationX(float a) {
  const float c = std::cos(a), s = std::sin(a);
  return fromRows(1, 0, 0, 0,
                  0, c, -s, 0,
                  0, s, c, 0,
                  0, 0, 0, 1);
}

glm::mat4 rotationY(float a) {
  const float c = std::cos(a), s = std::sin(a);
  return fromRows(c, 0, s, 0,
                  0, 1, 0, 0,
                  -s, 0, c, 0,
                  0, 0, 0, 1);
}

glm::mat4 rotationZ(float a) {
  const float c = std::cos(a), s = std::sin(a);
  return fromRows(c, -s, 0, 0,
                  s, c, 0, 0,
                  0, 0, 1, 0,
                  0, 0, 0, 1);
}

glm::mat4 shear(const ShearFactors& h) {
  return fromRows(1, h.hxy, h.hxz, 0,
                  h.hyx, 1, h.hyz, 0,
                  h.hzx, h.hzy, 1, 0,
                  0, 0, 0, 1);
}

glm::mat4 generalRotation(glm::vec3 i, glm::vec3 j, glm::vec3 k) {
  return fromRows(i.x, i.y, i.z, 0,
                  j.x, j.y, j.z, 0,
                  k.x, k.y, k.z, 0,
                  0, 0, 0, 1);
}

glm::mat4 rotationAboutAxis(glm::vec3 point, glm::vec3 axis, float angle) {
  // Build an orthonormal frame with k along the axis; any i perpendicular to k will do.
  const glm::vec3 k = glm::normalize(axis);
  const glm::vec3 helper = std::fabs(k.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 i = glm::normalize(glm::cross(helper, k));
  const glm::vec3 j = glm::cross(k, i);
  const glm::mat4 grm = generalRotation(i, j, k);
  return translation(point) * inverseRotation(grm) * rotationZ(angle) * grm * translation(-point);
}

glm::mat4 inverseTranslation(glm::vec3 t) { return translation(-t); }

glm::mat4 inverseScaling(glm::vec3 s) { return scaling(1.0f / s); }

glm::mat4 inverseRotation(const glm::mat4& rotation) { return glm::transpose(rotation); }

}  // namespace facet
