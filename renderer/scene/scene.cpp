#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

glm::vec3 pointAlong(glm::vec3 eye, glm::vec3 direction) {
  const float reach = std::max({std::fabs(eye.x), std::fabs(eye.y), std::fabs(eye.z)});
  const float scale = reach < 8192.0f ? 1.0f : std::exp2(std::ceil(std::log2(reach)));
  return eye + scale * direction;
}

// A box of float corners beyond ±1.8e19 overflows the float squares of its
// diagonal: then the radius is computed again in double (and is infinite
// only past float's range). Smaller boxes keep the float value, bit for bit.
float Bounds::radius() const {
  if (empty) return 0.0f;
  const float r = 0.5f * glm::length(max - min);
  if (std::isfinite(r)) return r;
  const glm::dvec3 d = glm::dvec3(max) - glm::dvec3(min);
  const double wide = 0.5 * std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  return wide <= static_cast<double>(std::numeric_limits<float>::max()) ? static_cast<float>(wide) : std::numeric_limits<float>::infinity();
}

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
  Bounds bounds = unmeshed;
  for (const MeshInstance& instance : instances) {
    const Mesh& mesh = meshes[static_cast<std::size_t>(instance.mesh)];
    for (const glm::vec3& p : mesh.positions) {
      const glm::vec3 world(instance.worldFromModel * glm::vec4(p, 1.0f));
      if (std::isfinite(world.x) && std::isfinite(world.y) && std::isfinite(world.z)) bounds.include(world);  // what can be framed
    }
  }
  return bounds;
}

}  // namespace facet
