// The watertight ray/triangle test (triangle_intersection.h): the per-ray
// shear, then per triangle the edge functions, their double fallback and t.
#include "ray/triangle_intersection.h"

#include <cmath>
#include <utility>

#include "ray/narrowing.h"

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

bool intersectTriangle(const WatertightRay& ray, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, TriangleHit& hit) {
  const glm::vec3 A = p0 - ray.origin, B = p1 - ray.origin, C = p2 - ray.origin;
  const int kx = ray.kx, ky = ray.ky, kz = ray.kz;
  const float Ax = A[kx] - ray.sx * A[kz], Ay = A[ky] - ray.sy * A[kz];
  const float Bx = B[kx] - ray.sx * B[kz], By = B[ky] - ray.sy * B[kz];
  const float Cx = C[kx] - ray.sx * C[kz], Cy = C[ky] - ray.sy * C[kz];

  float U = Cx * By - Cy * Bx;
  float V = Ax * Cy - Ay * Cx;
  float W = Bx * Ay - By * Ax;
  // A float 0 may hide either sign; a product of two floats is exact in
  // double, and the difference of two doubles has the exact sign.
  if (U == 0.0f || V == 0.0f || W == 0.0f) {
    U = toFloat(static_cast<double>(Cx) * By - static_cast<double>(Cy) * Bx);
    V = toFloat(static_cast<double>(Ax) * Cy - static_cast<double>(Ay) * Cx);
    W = toFloat(static_cast<double>(Bx) * Ay - static_cast<double>(By) * Ax);
  }
  if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f)) return false;

  const float det = U + V + W;
  // det = 0: the ray sees the triangle edge-on or it has no area. A corner
  // that is infinite or NaN makes det infinite or NaN (every product with it
  // is), and the test refuses it.
  if (det == 0.0f || !std::isfinite(det)) return false;

  const float Az = ray.sz * A[kz], Bz = ray.sz * B[kz], Cz = ray.sz * C[kz];
  const float T = U * Az + V * Bz + W * Cz;
  // tMin·det < T < tMax·det without dividing first: flip both signs when
  // det < 0 (the paper's xor with det's sign bit). NaN compares false.
  const float Tp = det < 0.0f ? -T : T, detp = det < 0.0f ? -det : det;
  if (!(Tp > ray.tMin * detp && Tp < ray.tMax * detp)) return false;

  const float inverseDet = 1.0f / det;
  const float t = T * inverseDet;
  // The division rounds: keep the promise tMin < t < tMax for the value
  // returned (and never return an overflowed t).
  if (!(t > ray.tMin && t < ray.tMax)) return false;
  hit.t = t;
  hit.u = V * inverseDet;
  hit.v = W * inverseDet;
  return true;
}

}  // namespace facet::ray
