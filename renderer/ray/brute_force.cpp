// Brute force (brute_force.h): each primitive in index order, kept as plain
// as the rule it stands for.
#include "ray/brute_force.h"

#include "ray/sphere_intersection.h"
#include "ray/triangle_intersection.h"

namespace facet::ray {
namespace {

// Calls hitFound(Hit) for every primitive the ray hits, in index order,
// until it returns true.
template <class Visit>
void forEachHit(const Primitives& primitives, const Ray& ray, Visit&& hitFound) {
  if (!canHit(ray)) return;
  const WatertightRay watertight = makeWatertightRay(ray);
  const std::size_t triangles = primitives.triangleCount(), count = primitives.count();
  for (std::size_t i = 0; i < count; ++i) {
    const auto index = static_cast<std::uint32_t>(i);
    Bounds bounds;
    if (!primitiveBounds(primitives, index, bounds)) continue;
    Hit hit;
    hit.primitive = index;
    if (i < triangles) {
      const glm::vec3* p = &primitives.triangleCorners[3 * i];
      TriangleHit h;
      if (!intersectTriangle(watertight, p[0], p[1], p[2], h)) continue;
      hit.t = h.t, hit.u = h.u, hit.v = h.v;
    } else {
      const glm::vec4 s = primitives.spheres[i - triangles];
      if (!intersectSphere(ray, glm::vec3(s), s.w, hit.t)) continue;
    }
    if (hitFound(hit)) return;
  }
}

}  // namespace

bool intersectBruteForce(const Primitives& primitives, const Ray& ray, Hit& hit) {
  checkPrimitiveCounts(primitives.triangleCorners.size(), primitives.spheres.size());
  bool found = false;
  forEachHit(primitives, ray, [&](const Hit& h) {
    if (!found || nearer(h, hit)) hit = h, found = true;
    return false;
  });
  return found;
}

bool occludedBruteForce(const Primitives& primitives, const Ray& ray) {
  checkPrimitiveCounts(primitives.triangleCorners.size(), primitives.spheres.size());
  bool found = false;
  forEachHit(primitives, ray, [&](const Hit&) { return found = true; });
  return found;
}

}  // namespace facet::ray
