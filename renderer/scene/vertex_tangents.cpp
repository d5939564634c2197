#include "scene/vertex_tangents.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace facet {

void computeVertexTangents(Mesh& mesh, int set) {
  const std::size_t n = mesh.positions.size();
  const std::vector<glm::vec2>& uv = mesh.texcoordSet(set);
  if (uv.size() != n) return;  // no such set: no tangents
  std::vector<glm::dvec3> alongS(n, glm::dvec3(0.0)), alongT(n, glm::dvec3(0.0));
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    if (a >= n || b >= n || c >= n) continue;
    const glm::dvec3 e1 = glm::dvec3(mesh.positions[b]) - glm::dvec3(mesh.positions[a]);
    const glm::dvec3 e2 = glm::dvec3(mesh.positions[c]) - glm::dvec3(mesh.positions[a]);
    const glm::dvec2 d1 = glm::dvec2(uv[b]) - glm::dvec2(uv[a]);
    const glm::dvec2 d2 = glm::dvec2(uv[c]) - glm::dvec2(uv[a]);
    const double r = d1.x * d2.y - d2.x * d1.y;
    if (!(std::fabs(r) > 0.0) || !std::isfinite(r)) continue;  // no texture-space area: no direction
    const glm::dvec3 s = (e1 * d2.y - e2 * d1.y) / r, t = (e2 * d1.x - e1 * d2.x) / r;
    if (!std::isfinite(s.x + s.y + s.z + t.x + t.y + t.z)) continue;
    for (const std::uint32_t v : {a, b, c}) alongS[v] += s, alongT[v] += t;
  }
  mesh.tangents.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    const glm::dvec3 N(mesh.normals[v]);
    glm::dvec3 T = alongS[v] - N * glm::dot(N, alongS[v]);
    if (!(glm::length(T) > 1e-12)) {  // any direction perpendicular to N
      T = std::fabs(N.x) < 0.9 ? glm::cross(N, glm::dvec3(1, 0, 0)) : glm::cross(N, glm::dvec3(0, 1, 0));
    }
    T = glm::normalize(T);
    // glTF's t grows down the image and its normal textures' +y points up it: B = w·(N × T) against ∂P/∂t.
    const double w = glm::dot(glm::cross(N, T), alongT[v]) > 0.0 ? -1.0 : 1.0;
    mesh.tangents[v] = glm::vec4(glm::vec3(T), static_cast<float>(w));
  }
}

int tangentSetOf(const Scene& scene, const Mesh& mesh) {
  if (mesh.material < 0 || static_cast<std::size_t>(mesh.material) >= scene.materials.size()) return 0;
  const Material& material = scene.materials[static_cast<std::size_t>(mesh.material)];
  return material.normalTexture >= 0 ? material.texcoordSets.normal : 0;
}

}  // namespace facet
