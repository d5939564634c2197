#include "math/projection.h"

#include <cmath>

#include "math/elementary.h"
#include "math/matrix_rows.h"

namespace facet {

glm::mat4 perspective(float theta, float aspect, float near, float far) {
  const float t = elementary::tan(theta);
  const float a = far / (far - near);
  const float b = -near * far / (far - near);
  return fromRows(1, 0, 0, 0,
                  0, aspect, 0, 0,
                  0, 0, a * t, b * t,
                  0, 0, t, 0);
}

glm::mat4 parallel(float width, float height, float near, float far) {
  return fromRows(2 / width, 0, 0, 0,
                  0, 2 / height, 0, 0,
                  0, 0, 1 / (far - near), -near / (far - near),
                  0, 0, 0, 1);
}

}  // namespace facet
