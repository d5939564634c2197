#pragma once
// The watertight ray/triangle test of Woop, Benthin and Wald, "Watertight
// Ray/Triangle Intersection", Journal of Computer Graphics Techniques
// 2(1):65-82, 2013.
//
// The ray is moved to the origin and sheared so that it runs along +z (its
// dominant axis kz becomes z; kx, ky are swapped when dir[kz] < 0 so the
// winding is kept): with Sx = dx/dz, Sy = dy/dz, Sz = 1/dz, a vertex p maps
// to A = p - o, (A[kx] - Sx·A[kz], A[ky] - Sy·A[kz], Sz·A[kz]). The hit is
// then a 2D question about the origin and the three sheared vertices, asked
// with the edge functions
//   U = Cx·By - Cy·Bx,  V = Ax·Cy - Ay·Cx,  W = Bx·Ay - By·Ax,
// which are the barycentric weights of p0, p1, p2 times det = U + V + W.
//
// What it guarantees: an edge shared by two triangles gives both the same
// edge function with opposite signs (the same products, subtracted the other
// way round), and rounding is monotonic, so a float edge function has the
// sign of the exact one for the sheared vertices or is 0; a 0 is decided
// again in double, where the products of floats are exact. So no
// ray passes between two triangles that share an edge, and a ray through a
// shared edge or vertex hits at least one of them. The test is conservative,
// not exact: the shear rounds the vertices by a few ulps of their distance
// from the origin, so a traversal's box test must be widened by as much
// (slab_test.h) to never miss what this test hits.
//
// Both faces are hit (U, V, W all >= 0 or all <= 0); culling is the caller's.
#include <cmath>

#include <glm/vec3.hpp>

#include "ray/narrowing.h"
#include "ray/ray.h"

namespace facet::ray {

// What the test needs of a ray, computed once per ray (the paper's
// per-ray precomputation), not once per triangle.
struct WatertightRay {
  glm::vec3 origin{0.0f};  // world space
  int kx = 0, ky = 1, kz = 2;  // kz: the axis where |direction| is largest
  float sx = 0.0f, sy = 0.0f, sz = 1.0f;  // the shear: dir[kx]/dir[kz], dir[ky]/dir[kz], 1/dir[kz]
  float tMin = 0.0f, tMax = 0.0f;  // the ray's open interval
};

WatertightRay makeWatertightRay(const Ray& ray);

struct TriangleHit {
  float t = 0.0f;
  float u = 0.0f, v = 0.0f;  // P = (1 - u - v)·p0 + u·p1 + v·p2
};

// True when the ray hits the triangle p0 p1 p2 (world space) at a t with
// tMin < t < tMax. Never hits a triangle of zero area as the ray sees it
// (det = 0), nor one with an infinite or NaN corner, nor for a ray with a
// zero, infinite or NaN direction.
inline bool intersectTriangle(const WatertightRay& ray, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, TriangleHit& hit) {
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
