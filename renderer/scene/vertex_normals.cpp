#include "scene/vertex_normals.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace facet {

void computeVertexNormals(Mesh& mesh) {
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const glm::vec3 areaNormal = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    if (!std::isfinite(areaNormal.x + areaNormal.y + areaNormal.z)) continue;
    mesh.normals[a] += areaNormal;
    mesh.normals[b] += areaNormal;
    mesh.normals[c] += areaNormal;
  }
  for (glm::vec3& n : mesh.normals) {
    const float length = glm::length(n);
    n = length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
  }
}

}  // namespace facet
