#pragma once
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

namespace facet {

// Normals transform by (TM^T)^-1, upper 3x3 (course): it keeps them
// perpendicular to surfaces under non-uniform scaling and shear. The result
// is not normalized; normalize each transformed normal.
glm::mat3 normalMatrix(const glm::mat4& worldFromModel);

}  // namespace facet
