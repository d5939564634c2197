#pragma once
// The geometry a ray can hit: triangles (three world-space corners each) and
// spheres (centre, radius). One index names a primitive everywhere (Hit,
// BVH, brute force): index i < triangleCount() is triangle i, made of
// corners 3i, 3i+1, 3i+2; index triangleCount() + j is sphere j. Indices
// are stable: adding spheres never renumbers triangles.
//
// A primitive whose bounding box is not finite (an infinite or NaN corner,
// centre or radius, or a sphere reaching beyond float's range) is never hit:
// the BVH leaves it out and brute force skips it, by the same rule
// (primitiveBounds). Zero-area triangles and zero-radius spheres are kept;
// the tests decide what they hit.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "ray/bounds.h"

namespace facet::ray {

struct Primitives {
  std::vector<glm::vec3> triangleCorners;  // world space, 3 per triangle
  std::vector<glm::vec4> spheres;          // world space: centre xyz, radius w

  std::size_t triangleCount() const { return triangleCorners.size() / 3; }
  std::size_t sphereCount() const { return spheres.size(); }
  std::size_t count() const { return triangleCount() + sphereCount(); }
  bool isSphere(std::uint32_t primitive) const { return primitive >= triangleCount(); }
};

// Throws facet::Error when the counts overflow the node format (above
// kMaxTracedPrimitives together, vocabulary/limits.h) or when the corners
// are not a whole number of triangles.
void checkPrimitiveCounts(std::size_t cornerCount, std::size_t sphereCount);

// The primitive's box (a sphere's rounded outwards, so it contains the
// sphere); false when that box is not finite, and then the primitive is
// never hit.
bool primitiveBounds(const Primitives& primitives, std::uint32_t primitive, Bounds& bounds);

}  // namespace facet::ray
