#include "scene/primitives.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <glm/geometric.hpp>

namespace facet {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

std::uint32_t addVertex(Mesh& mesh, glm::vec3 position, glm::vec3 normal, glm::vec2 uv) {
  mesh.positions.push_back(position);
  mesh.normals.push_back(glm::normalize(normal));
  mesh.texcoords.push_back(uv);
  return static_cast<std::uint32_t>(mesh.positions.size() - 1);
}

// Adds triangle (a, b, c), turned so that it runs counter-clockwise seen from
// the side its vertex normals point to. Zero-area triangles (at poles) are skipped.
void addTriangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const glm::vec3 geometric = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
  if (glm::length(geometric) <= 1e-12f) return;
  const glm::vec3 shading = mesh.normals[a] + mesh.normals[b] + mesh.normals[c];
  if (glm::dot(geometric, shading) < 0.0f) std::swap(b, c);
  mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// A (columns+1)×(rows+1) grid of vertices from surface(u, v) -> {position, normal},
// u, v in [0, 1], two triangles per cell. On a closed surface the last column
// (row) is evaluated at u = 0 (v = 0) again, so that seam vertices are
// bit-identical and the rasterizer sees one shared edge, not a crack.
struct SurfacePoint {
  glm::vec3 position, normal;
};
struct Wrap {
  bool u = false, v = false;
};
void addGrid(Mesh& mesh, int columns, int rows, Wrap wrap, const std::function<SurfacePoint(float, float)>& surface) {
  const auto first = static_cast<std::uint32_t>(mesh.positions.size());
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c <= columns; ++c) {
      const float u = static_cast<float>(c) / static_cast<float>(columns);
      const float v = static_cast<float>(r) / static_cast<float>(rows);
      const SurfacePoint p = surface(wrap.u && c == columns ? 0.0f : u, wrap.v && r == rows ? 0.0f : v);
      addVertex(mesh, p.position, p.normal, {u, v});
    }
  const auto at = [&](int c, int r) { return first + static_cast<std::uint32_t>(r * (columns + 1) + c); };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      addTriangle(mesh, at(c, r + 1), at(c + 1, r + 1), at(c + 1, r));
      addTriangle(mesh, at(c, r + 1), at(c + 1, r), at(c, r));
    }
}

}  // namespace

Mesh makeSphere(int level) {
  level = std::max(level, 2);
  Mesh mesh;
  mesh.name = "sphere";
  mesh.sphere = true;
  addGrid(mesh, 2 * level, level, {true, false}, [](float u, float v) {
    const float theta = kTwoPi * u, phi = std::numbers::pi_v<float> * v;
    // Exactly on the axis at the poles (float sin(π) is not 0), so pole
    // triangles are exactly degenerate and dropped.
    const float ring = v == 0.0f || v == 1.0f ? 0.0f : std::sin(phi);
    const glm::vec3 p{ring * std::sin(theta), std::cos(phi), ring * std::cos(theta)};
    return SurfacePoint{p, p};
  });
  return mesh;
}

Mesh makeCube() {
  Mesh mesh;
  mesh.name = "cube";
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {1.0f, -1.0f}) {
      const glm::vec3 n = sign * axes[axis];
      const glm::vec3 s = axes[(axis + 1) % 3], t = axes[(axis + 2) % 3];
      addGrid(mesh, 1, 1, {}, [&](float u, float v) {
        return SurfacePoint{n + (2 * u - 1) * s + (2 * v - 1) * t, n};
      });
    }
  return mesh;
}

Mesh makePlane(int subdivisions) {
  subdivisions = std::max(subdivisions, 1);
  Mesh mesh;
  mesh.name = "plane";
  addGrid(mesh, subdivisions, subdivisions, {}, [](float u, float v) {
    return SurfacePoint{{2 * u - 1, 0.0f, 2 * v - 1}, {0, 1, 0}};
  });
  return mesh;
}

Mesh makeCylinder(int segments) {
  segments = std::max(segments, 3);
  Mesh mesh;
  mesh.name = "cylinder";
  addGrid(mesh, segments, 1, {true, false}, [](float u, float v) {
    const float theta = kTwoPi * u;
    const glm::vec3 radial{std::sin(theta), 0.0f, std::cos(theta)};
    return SurfacePoint{radial + glm::vec3(0.0f, 1.0f - 2.0f * v, 0.0f), radial};
  });
  for (float side : {1.0f, -1.0f}) {  // caps: triangle fans around their centres
    const glm::vec3 n{0.0f, side, 0.0f};
    const std::uint32_t centre = addVertex(mesh, n, n, {0.5f, 0.5f});
    const auto rim = static_cast<std::uint32_t>(mesh.positions.size());
    for (int s = 0; s <= segments; ++s) {
      const float theta = s == segments ? 0.0f : kTwoPi * static_cast<float>(s) / static_cast<float>(segments);
      addVertex(mesh, {std::sin(theta), side, std::cos(theta)}, n, {0.5f + 0.5f * std::sin(theta), 0.5f + 0.5f * std::cos(theta)});
    }
    for (int s = 0; s < segments; ++s) addTriangle(mesh, centre, rim + static_cast<std::uint32_t>(s), rim + static_cast<std::uint32_t>(s + 1));
  }
  return mesh;
}

Mesh makeTorus(float major, float minor, int ringSegments, int tubeSegments) {
  Mesh mesh;
  mesh.name = "torus";
  addGrid(mesh, std::max(ringSegments, 3), std::max(tubeSegments, 3), {true, true}, [=](float u, float v) {
    const float theta = kTwoPi * u, alpha = -kTwoPi * v;
    const glm::vec3 radial{std::sin(theta), 0.0f, std::cos(theta)};
    const glm::vec3 normal = std::cos(alpha) * radial + glm::vec3(0.0f, std::sin(alpha), 0.0f);
    return SurfacePoint{major * radial + minor * normal, normal};
  });
  return mesh;
}

}  // namespace facet
