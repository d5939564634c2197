// The watertight ray/triangle test (triangle_intersection.h): the per-ray
// shear (per triangle, the test itself is inline in the header: the BVH's leaves call it in their inner loop).
#include "ray/triangle_intersection.h"

#include <cmath>
#include <utility>


namespace facet::ray {

WatertightRay makeWatertightRay(const Ray& ray) {
  WatertightRay r;
  r.origin = ray.origin;
  r.tMin = ray.tMin;
  r.tMax = ray.tMax;
  const glm::vec3 d = ray.direction;
  const glm::vec3 a = glm::vec3(std::fabs(d.x), std::fabs(d.y), std::fabs(d.z));
  r.kz = a.y > a.x ? 1 : 0;
  if (a.z > a[r.kz]) r.kz = 2;
  r.kx = r.kz == 2 ? 0 : r.kz + 1;
  r.ky = r.kx == 2 ? 0 : r.kx + 1;
  if (d[r.kz] < 0.0f) std::swap(r.kx, r.ky);  // keeps the winding: the paper's swap
  r.sx = d[r.kx] / d[r.kz];
  r.sy = d[r.ky] / d[r.kz];
  r.sz = 1.0f / d[r.kz];
  return r;
}

}  // namespace facet::ray
