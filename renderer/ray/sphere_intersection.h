#pragma once
// The course's ray/sphere test. With the ray P = O + tD and the sphere
// |P - C|² = r², t solves A·t² + B·t + C' = 0 where
//   A = D·D,  B = 2·D·(O - C),  C' = |O - C|² - r²,
// no hit when the discriminant B² - 4AC' is negative, else the nearer root
// inside (tMin, tMax): the smaller, else the larger, so that a ray starting
// inside the sphere hits its far side.
//
// The roots come from q = -(B + sign(B)·sqrt(B² - 4AC'))/2 as t0 = q/A and
// t1 = C'/q (Numerical Recipes, 3rd ed., section 5.6): the textbook
// (-B ± sqrt(disc))/2A subtracts two nearly equal numbers for the root
// nearer 0 whenever 4AC' is small against B², and loses its digits; q never
// subtracts. Everything runs in double: the discriminant of a grazing ray is
// the difference of two large, nearly equal terms, and in float it decides
// hit or miss several ulps away from the true silhouette.
#include <cmath>
#include <utility>

#include <glm/vec3.hpp>

#include "ray/narrowing.h"
#include "ray/ray.h"

namespace facet::ray {

// True when the ray hits the sphere (world space centre and radius; its sign
// does not matter) at a t with tMin < t < tMax, the t being that of the float
// returned. A sphere of radius 0 is hit only by a ray through its centre.
inline bool intersectSphere(const Ray& ray, const glm::vec3& centre, float radius, float& t) {
  const double fx = static_cast<double>(ray.origin.x) - centre.x;
  const double fy = static_cast<double>(ray.origin.y) - centre.y;
  const double fz = static_cast<double>(ray.origin.z) - centre.z;
  const double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
  const double r = radius;
  const double A = dx * dx + dy * dy + dz * dz;
  const double B = 2.0 * (dx * fx + dy * fy + dz * fz);
  const double C = (fx * fx + fy * fy + fz * fz) - r * r;
  const double discriminant = B * B - 4.0 * A * C;
  if (!(discriminant >= 0.0) || !(A > 0.0) || !std::isfinite(A)) return false;  // NaN fails too
  const double q = -0.5 * (B + std::copysign(std::sqrt(discriminant), B));
  // q = 0 only when B = 0 and disc = 0, so C' = 0: a tangent ray starting
  // on the sphere, both roots 0.
  double t0 = q / A, t1 = q != 0.0 ? C / q : t0;
  if (t1 < t0) std::swap(t0, t1);
  const float near = toFloat(t0), far = toFloat(t1);
  if (near > ray.tMin && near < ray.tMax) {
    t = near;
    return true;
  }
  if (far > ray.tMin && far < ray.tMax) {
    t = far;
    return true;
  }
  return false;
}

}  // namespace facet::ray
