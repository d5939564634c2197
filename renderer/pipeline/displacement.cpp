#include "pipeline/displacement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <utility>

#include <glm/geometric.hpp>

#include "common/error.h"
#include "image/png.h"
#include "scene/memory_budget.h"
#include "scene/vertex_normals.h"
#include "scene/vertex_tangents.h"

namespace facet {
namespace {

// Four triangles for each of `mesh`, by its edge midpoints, each made once per edge.
void subdivide(Mesh& mesh) {
  const bool colored = !mesh.colors.empty(), withSet1 = !mesh.texcoords1.empty();
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
  const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
    const std::pair<std::uint32_t, std::uint32_t> key = std::minmax(a, b);
    const auto found = midpoints.find(key);
    if (found != midpoints.end()) return found->second;
    const auto m = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.push_back((mesh.positions[a] + mesh.positions[b]) * 0.5f);
    mesh.normals.push_back(glm::normalize(mesh.normals[a] + mesh.normals[b]));
    mesh.texcoords.push_back((mesh.texcoords[a] + mesh.texcoords[b]) * 0.5f);
    if (withSet1) mesh.texcoords1.push_back((mesh.texcoords1[a] + mesh.texcoords1[b]) * 0.5f);
    if (colored) mesh.colors.push_back((mesh.colors[a] + mesh.colors[b]) * 0.5f);
    midpoints.emplace(key, m);
    return m;
  };
  std::vector<std::uint32_t> indices;
  indices.reserve(mesh.indices.size() * 4);
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    indices.insert(indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
  }
  mesh.indices = std::move(indices);
}

}  // namespace

Image loadHeightMap(const std::string& path) {
  Image image = readPng(path);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Rgba8 p = image.at(x, y);
      if (p.r != p.g || p.g != p.b)
        throw Error(path + ": not a greyscale height map: pixel (" + std::to_string(x) + ", " + std::to_string(image.height() - 1 - y) +
                    ") from the top left is (" + std::to_string(p.r) + ", " + std::to_string(p.g) + ", " + std::to_string(p.b) + ")");
    }
  return image;
}

double heightAt(const Image& heights, double s, double t) {
  const int w = heights.width(), h = heights.height();
  const double x = s * w - 0.5, y = (1.0 - t) * h - 0.5;
  if (!std::isfinite(x) || !std::isfinite(y)) return 0.0;
  const double x0 = std::floor(x), y0 = std::floor(y), fx = x - x0, fy = y - y0;
  const auto grey = [&](double i, double j) {
    const auto wrapped = [](double k, int n) { return static_cast<int>(k - std::floor(k / n) * n) % n; };
    return heights.at(wrapped(i, w), wrapped(j, h)).r / 255.0;
  };
  const double bottom = grey(x0, y0) * (1 - fx) + grey(x0 + 1, y0) * fx;
  const double top = grey(x0, y0 + 1) * (1 - fx) + grey(x0 + 1, y0 + 1) * fx;
  return bottom * (1 - fy) + top * fy;
}

void displaceMeshes(Scene& scene, const Image& heights, float scale, int subdivisions) {
  // Priced first, exactly: each subdivision adds a vertex per edge (E' = 2E + 3T) and
  // quadruples the triangles; the meshes against the scene budget, their instances'
  // frame buffers against the frame budget, so a refusal comes before any work.
  MemoryBudget sceneBudget(kSceneMemoryBudget, "scene budget"), frameBudget(kFrameMemoryBudget, "frame budget");
  std::vector<std::uint64_t> verticesAfter(scene.meshes.size()), trianglesAfter(scene.meshes.size());
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    std::uint64_t vertices = mesh.positions.size(), triangles = mesh.triangleCount();
    if (!mesh.texcoords.empty()) {
      std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
      for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) edges.insert(std::minmax(mesh.indices[t + e], mesh.indices[t + (e + 1) % 3]));
      std::uint64_t edgeCount = edges.size();
      for (int k = 0; k < subdivisions; ++k) vertices += edgeCount, edgeCount = 2 * edgeCount + 3 * triangles, triangles *= 4;
      const std::string what = "material.displacementSubdivisions: meshes[" + std::to_string(m) + "] '" + mesh.name + "' subdivided " +
                               std::to_string(subdivisions) + " times: " + std::to_string(vertices) + " vertices and " + std::to_string(triangles) +
                               " triangles";
      const std::uint64_t perVertex = 2 * sizeof(glm::vec3) + sizeof(glm::vec2) + (mesh.texcoords1.empty() ? 0 : sizeof(glm::vec2)) +
                                      (mesh.colors.empty() ? 0 : sizeof(glm::vec4)) +
                                      (mesh.tangents.empty() ? 0 : sizeof(glm::vec4));
      sceneBudget.charge(vertices * perVertex + triangles * 3 * sizeof(std::uint32_t), what);
    }
    verticesAfter[m] = vertices, trianglesAfter[m] = triangles;
  }
  for (const MeshInstance& instance : scene.instances) {
    if (instance.mesh < 0 || static_cast<std::size_t>(instance.mesh) >= scene.meshes.size()) continue;  // refused by checkScene
    const auto m = static_cast<std::size_t>(instance.mesh);
    frameBudget.charge(instanceFrameBytes(verticesAfter[m], trianglesAfter[m]),
                       "material.displacementSubdivisions: an instance of meshes[" + std::to_string(m) + "] '" + scene.meshes[m].name + "' subdivided " +
                           std::to_string(subdivisions) + " times: " + std::to_string(verticesAfter[m]) + " vertices and " +
                           std::to_string(trianglesAfter[m]) + " triangles");
  }
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    Mesh& mesh = scene.meshes[m];
    if (mesh.texcoords.empty()) {
      scene.warnings.push_back("meshes[" + std::to_string(m) + "] '" + mesh.name + "': no TEXCOORD_0 to read the height map at; not displaced");
      continue;
    }
    for (int k = 0; k < subdivisions; ++k) subdivide(mesh);
    mesh.sphere = false;  // displaced, it is no longer the sphere the ray tracer could trace in its place
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const double h = heightAt(heights, mesh.texcoords[v].x, mesh.texcoords[v].y);
      mesh.positions[v] += static_cast<float>(scale * h) * mesh.normals[v];
    }
    computeVertexNormals(mesh);
    if (!mesh.tangents.empty()) computeVertexTangents(mesh, tangentSetOf(scene, mesh));  // the displaced surface's, as its normals
  }
  scene.identity.renew();
}

std::string displacementKey(const MaterialOverrides& material) {
  if (material.displacementMap.empty()) return "";
  char numbers[64];
  std::snprintf(numbers, sizeof numbers, " x %.9g, %d subdivisions", static_cast<double>(material.displacementScale), material.displacementSubdivisions);
  return material.displacementMap + numbers;
}

}  // namespace facet
