// Primitive counts and boxes (primitives.h): the checks every builder and
// brute force share, so they agree on what can be hit.
#include "ray/primitives.h"

#include <cmath>
#include <string>

#include "common/error.h"
#include "ray/narrowing.h"
#include "vocabulary/limits.h"

namespace facet::ray {

void checkPrimitiveCounts(std::size_t cornerCount, std::size_t sphereCount) {
  if (cornerCount % 3 != 0)
    throw Error("ray tracing: " + std::to_string(cornerCount) + " triangle corners are not a whole number of triangles");
  const std::size_t triangles = cornerCount / 3;
  if (triangles > kMaxTracedPrimitives || sphereCount > kMaxTracedPrimitives - triangles)
    throw Error("ray tracing: " + std::to_string(triangles) + " triangles and " + std::to_string(sphereCount) +
                " spheres are more than the " + std::to_string(kMaxTracedPrimitives) + " primitives a BVH can index");
}

namespace {

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

bool primitiveBounds(const Primitives& primitives, std::uint32_t primitive, Bounds& bounds) {
  bounds = Bounds{};
  const std::size_t triangles = primitives.triangleCount();
  if (primitive < triangles) {
    for (std::size_t k = 0; k < 3; ++k) {
      const glm::vec3& p = primitives.triangleCorners[3 * std::size_t{primitive} + k];
      if (!finite(p)) return false;  // min and max would pass over a NaN
      bounds.grow(p);
    }
  } else {
    const glm::vec4 s = primitives.spheres[primitive - triangles];
    const double r = std::fabs(static_cast<double>(s.w));
    for (int a = 0; a < 3; ++a) {
      bounds.lower[a] = toFloatDown(static_cast<double>(s[a]) - r);
      bounds.upper[a] = toFloatUp(static_cast<double>(s[a]) + r);
    }
  }
  return finite(bounds.lower) && finite(bounds.upper);
}

}  // namespace facet::ray
