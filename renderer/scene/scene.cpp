#include "scene/scene.h"

#include <utility>

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

int Scene::addMaterial(std::string name, glm::vec3 color, float metallic, float roughness) {
  identity.renew();
  Material m;
  m.name = std::move(name);
  m.baseColor = glm::vec4(color, 1.0f);
  m.metallic = metallic;
  m.roughness = roughness;
  materials.push_back(std::move(m));
  return static_cast<int>(materials.size() - 1);
}

void Scene::addObject(Mesh mesh, int material, const glm::mat4& worldFromModel) {
  identity.renew();
  mesh.material = material;
  meshes.push_back(std::move(mesh));
  instances.push_back({static_cast<int>(meshes.size() - 1), worldFromModel});
}

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
