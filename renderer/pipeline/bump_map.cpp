#include "pipeline/bump_map.h"

#include "common/error.h"
#include "pipeline/displacement.h"
#include "scene/memory_budget.h"
#include "scene/vertex_tangents.h"

namespace facet {

void useBumpMap(Scene& scene, const MaterialOverrides& material) {
  if (material.bumpMap == scene.bumpMapPath) return;
  if (!scene.bumpMapPath.empty()) throw Error("material.bumpMap: the scene already has the bump map " + scene.bumpMapPath);
  try {
    Texture heights;
    heights.name = material.bumpMap;
    heights.image = loadHeightMap(material.bumpMap);
    heights.encoding = TexelEncoding::Linear;
    MemoryBudget budget(kSceneMemoryBudget, "scene budget");
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
      const Mesh& mesh = scene.meshes[m];
      if (!mesh.texcoords.empty() && mesh.tangents.empty())
        budget.charge(mesh.positions.size() * sizeof(glm::vec4),
                      "material.bumpMap: tangents for meshes[" + std::to_string(m) + "] '" + mesh.name + "'");
    }
    for (Mesh& mesh : scene.meshes)
      if (!mesh.texcoords.empty() && mesh.tangents.empty()) computeVertexTangents(mesh);
    scene.bumpMap = std::move(heights);
  } catch (const Error& e) {
    const std::string what = e.what();
    throw Error(what.rfind("material.", 0) == 0 ? what : "material.bumpMap: " + what);
  }
  scene.bumpMapPath = material.bumpMap;
  scene.identity.renew();
}

}  // namespace facet
