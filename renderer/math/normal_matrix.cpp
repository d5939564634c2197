#include "math/normal_matrix.h"

#include <glm/matrix.hpp>

namespace facet {

glm::mat3 normalMatrix(const glm::mat4& worldFromModel) {
  return glm::transpose(glm::inverse(glm::mat3(worldFromModel)));
}

}  // namespace facet
