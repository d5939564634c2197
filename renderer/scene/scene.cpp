#include "scene/scene.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace facet {

void Bounds::include(glm::vec3 p) {
  if (empty) {
    min = max = p;
    empty = false;
  } else {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
}

float Bounds::radius() const { return empty ? 0.0f : 0.5f * glm::length(max - min); }

std::size_t Scene::triangleCount() const {
  std::size_t count = 0;
  for (const MeshInstance& instance : instances) count += meshes[static_cast<std::size_t>(instance.mesh)].triangleCount();
  return count;
}

Bounds Scene::worldBounds() const {
  Bounds bounds;
  for (const MeshInstance& instance : instances) {
    const Mesh& mesh = meshes[static_cast<std::size_t>(instance.mesh)];
    for (const glm::vec3& p : mesh.positions) bounds.include(glm::vec3(instance.worldFromModel * glm::vec4(p, 1.0f)));
  }
  return bounds;
}

}  // namespace facet
