#pragma once
// A ray and the hit the ray-tracing backend reports for it. Everything here
// is in world space; t counts lengths of the direction, which need not be
// unit length, so a point on the ray is origin + t·direction.
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

namespace facet::ray {

struct Ray {
  glm::vec3 origin{0.0f};     // world space
  glm::vec3 direction{0.0f};  // world space, any length
  float tMin = 0.0f;          // a hit needs tMin < t < tMax (both open)
  float tMax = std::numeric_limits<float>::infinity();
};

struct Hit {
  float t = 0.0f;               // in lengths of Ray::direction
  std::uint32_t primitive = 0;  // Primitives' index: triangles first, then spheres (primitives.h)
  // Barycentrics on a triangle, P = (1 - u - v)·p0 + u·p1 + v·p2; 0 on a sphere.
  float u = 0.0f, v = 0.0f;
};

// The order of hits along a ray: the smaller t first and, at exactly the
// same t, the smaller primitive index, so that the nearest hit does not
// depend on the order primitives are visited in (the BVH and brute force
// give the same one).
inline bool nearer(const Hit& a, const Hit& b) { return a.t < b.t || (a.t == b.t && a.primitive < b.primitive); }

// A ray with an infinite or NaN origin, or a direction that is NaN or zero,
// hits nothing: the primitive tests refuse it, and the BVH and brute force
// stop before testing anything (a zero direction would otherwise pass every
// box that the origin lies in, or at t = infinity beyond).
inline bool canHit(const Ray& ray) {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(ray.origin[a]) || std::isnan(ray.direction[a])) return false;
  return ray.direction.x != 0.0f || ray.direction.y != 0.0f || ray.direction.z != 0.0f;
}

}  // namespace facet::ray
