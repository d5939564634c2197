// Procedural primitives: counts, outward unit normals, counter-clockwise winding.
#include <cmath>
#include <map>
#include <tuple>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "scene/default_scene.h"
#include "scene/primitives.h"
#include "scene/vertex_normals.h"

using namespace facet;

namespace {

// Every triangle's geometric normal agrees with its vertex normals (CCW seen
// from the side the normals point to) and points away from the solid's inside.
void checkOrientation(const Mesh& mesh, bool convex) {
  REQUIRE(mesh.indices.size() % 3 == 0);
  REQUIRE(mesh.normals.size() == mesh.positions.size());
  int bad = 0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]], c = mesh.positions[mesh.indices[t + 2]];
    const glm::vec3 geometric = glm::cross(b - a, c - a);
    const glm::vec3 shading = mesh.normals[mesh.indices[t]] + mesh.normals[mesh.indices[t + 1]] + mesh.normals[mesh.indices[t + 2]];
    if (!(glm::length(geometric) > 0.0f) || glm::dot(geometric, shading) <= 0.0f) ++bad;
    if (convex && glm::dot(geometric, (a + b + c) / 3.0f) <= 0.0f) ++bad;
  }
  CHECK(bad == 0);
  for (const glm::vec3& n : mesh.normals) CHECK(glm::length(n) == doctest::Approx(1.0f));
}

// A closed surface: every edge (by position) is used once in each direction.
void checkClosed(const Mesh& mesh) {
  const auto key = [](glm::vec3 p) { return std::make_tuple(std::lround(p.x * 1e4), std::lround(p.y * 1e4), std::lround(p.z * 1e4)); };
  std::map<std::pair<decltype(key({})), decltype(key({}))>, int> edges;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      const auto from = key(mesh.positions[mesh.indices[t + static_cast<std::size_t>(e)]]);
      const auto to = key(mesh.positions[mesh.indices[t + static_cast<std::size_t>((e + 1) % 3)]]);
      ++edges[{from, to}];
    }
  int unmatched = 0;
  for (const auto& [edge, count] : edges)
    if (count != 1 || !edges.count({edge.second, edge.first})) ++unmatched;
  CHECK(unmatched == 0);
}

}  // namespace

TEST_CASE("sphere: 4·level·(level-1) triangles, radius 1, outward, closed") {
  for (int level : {2, 5, 16}) {
    const Mesh sphere = makeSphere(level);
    CHECK(sphere.triangleCount() == static_cast<std::size_t>(4 * level * (level - 1)));
    for (const glm::vec3& p : sphere.positions) CHECK(glm::length(p) == doctest::Approx(1.0f));
    checkOrientation(sphere, true);
    checkClosed(sphere);
  }
}

TEST_CASE("cube: 12 triangles, face normals, closed") {
  const Mesh cube = makeCube();
  CHECK(cube.triangleCount() == 12);
  checkOrientation(cube, true);
  checkClosed(cube);
}

TEST_CASE("plane faces +y") {
  const Mesh plane = makePlane(4);
  CHECK(plane.triangleCount() == 32);
  checkOrientation(plane, false);
  for (std::size_t t = 0; t < plane.indices.size(); t += 3) {
    const glm::vec3 a = plane.positions[plane.indices[t]], b = plane.positions[plane.indices[t + 1]], c = plane.positions[plane.indices[t + 2]];
    CHECK(glm::cross(b - a, c - a).y > 0.0f);
  }
}

TEST_CASE("cylinder and torus are closed and outward") {
  const Mesh cylinder = makeCylinder(24);
  CHECK(cylinder.triangleCount() == 24 * 2 + 24 * 2);
  checkOrientation(cylinder, true);
  checkClosed(cylinder);
  const Mesh torus = makeTorus(0.7f, 0.3f, 32, 12);
  CHECK(torus.triangleCount() == 32 * 12 * 2);
  checkOrientation(torus, false);
  checkClosed(torus);
  for (std::size_t v = 0; v < torus.positions.size(); ++v) {  // normal points away from the tube's centre line
    const glm::vec3 p = torus.positions[v];
    const glm::vec3 ring = 0.7f * glm::normalize(glm::vec3(p.x, 0.0f, p.z));
    CHECK(glm::dot(torus.normals[v], p - ring) > 0.0f);
  }
}

TEST_CASE("vertex normals are area-weighted averages (course rule)") {
  // Two triangles meeting at vertex 0: a big one in the xy plane (area 2) and
  // a small one in the xz plane (area 0.5). The normal leans 4:1 toward +z.
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1}, {1, 0, 0}};
  mesh.indices = {0, 1, 2, 0, 3, 4};
  computeVertexNormals(mesh);
  const glm::vec3 expected = glm::normalize(glm::vec3(0, 4, 0) * 0.25f + glm::vec3(0, 0, 4));
  CHECK(mesh.normals[0].x == doctest::Approx(expected.x));
  CHECK(mesh.normals[0].y == doctest::Approx(expected.y));
  CHECK(mesh.normals[0].z == doctest::Approx(expected.z));
  CHECK(mesh.normals[1].z == doctest::Approx(1.0f));
}

TEST_CASE("default scene: ground, four primitives, one shadow-casting light, a camera") {
  const Scene scene = makeDefaultScene();
  CHECK(scene.instances.size() == 5);
  CHECK(scene.materials.size() == 5);
  REQUIRE(scene.lights.size() == 1);
  CHECK(scene.lights[0].castsShadow);
  REQUIRE(scene.cameras.size() == 1);
  CHECK(scene.warnings.empty());
  const Bounds b = scene.worldBounds();
  CHECK(b.min.y == doctest::Approx(0.0f).epsilon(1e-5));  // everything stands on the ground plane
  CHECK(b.max.x == doctest::Approx(5.0f));
  CHECK(scene.triangleCount() == 2 * 32 * 32 + 4 * 32 * 31 + 12 + 48 * 4 + 64 * 24 * 2);  // plane 32², sphere 32, cube, cylinder 48, torus 64×24
}
