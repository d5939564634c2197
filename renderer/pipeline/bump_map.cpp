#include "pipeline/bump_map.h"

#include <utility>

#include "common/error.h"
#include "scene/memory_budget.h"
#include "vocabulary/limits.h"
#include "scene/vertex_tangents.h"

namespace facet {

void useBumpMap(Scene& scene, const std::string& path, const Image& heights) {
  MemoryBudget budget(kSceneMemoryBudget, "scene budget");
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    if (!mesh.texcoords.empty() && mesh.tangents.empty())
      budget.charge(mesh.positions.size() * sizeof(glm::vec4), "material.bumpMap: tangents for meshes[" + std::to_string(m) + "] '" + mesh.name + "'");
  }
  for (Mesh& mesh : scene.meshes)
    if (!mesh.texcoords.empty() && mesh.tangents.empty()) computeVertexTangents(mesh);
  Texture texture;
  texture.name = path;
  texture.image = heights;
  texture.encoding = TexelEncoding::Linear;
  scene.bumpMap = std::move(texture);
  scene.bumpMapPath = path;
  scene.identity.renew();
}

}  // namespace facet
