#pragma once
// Scenes and rays for the ray-tracing tests: seeded random primitive sets
// with the awkward cases mixed in, closed meshes and flat grids whose
// shared corners are the same floats in every triangle, and bitwise hit
// comparison.
#include <cstdint>
#include <utility>
#include <vector>

#include "ray/primitives.h"
#include "ray/ray.h"

namespace facet::ray::test {

// What a random scene leans towards.
enum class SceneKind {
  Scattered,   // triangles of sizes from 1e-3 to 5 and spheres, all over a 20-unit box
  Clustered,   // tight clusters of small primitives under a few large triangles
  Coincident,  // the same triangles and spheres several times, at different indices
  Slivers,     // needles, axis-aligned flat triangles, zero-area ones, zero-radius spheres
  Broken,      // the above with infinite and NaN corners, centres and radii among them
};

Primitives randomScene(SceneKind kind, std::uint32_t seed, int count);

// Rays from inside and outside the scene: random directions, axis-aligned
// ones with +0 and -0 components, ones aimed exactly at corners, edge
// midpoints and sphere centres, varied lengths and intervals, and a few
// with a NaN or infinite origin or direction.
std::vector<Ray> randomRays(const Primitives& primitives, std::uint32_t seed, int count);

// A closed triangle mesh, rotated and moved off the axes; every shared
// corner is one float triple.
struct ClosedMesh {
  Primitives primitives;
  std::vector<glm::vec3> vertices;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;  // vertex indices
  glm::vec3 centre{0.0f};
  float inradius = 0.0f;  // every point closer than this to the centre is inside
};

// The icosahedron, each face cut in four `subdivisions` times, on the sphere.
ClosedMesh icosphere(int subdivisions, std::uint32_t seed);

// Bit for bit: the same primitive and the same t, u, v.
bool sameHit(const Hit& a, const Hit& b);

}  // namespace facet::ray::test
