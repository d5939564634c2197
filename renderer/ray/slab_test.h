#pragma once
// The ray/box test of the BVH traversal: Kay and Kajiya's slabs ("Ray
// Tracing Complex Scenes", SIGGRAPH 1986), made conservative so that a box
// is never missed when a primitive inside it would be hit. Each axis gives
// the t at which the ray enters and leaves the slab between the box's two
// planes, t = (plane - origin) · (1/direction); the ray crosses the box
// when the largest entry is at most the smallest exit.
//
// Three things could make a box test miss what the primitive test hits,
// and one allowance per ray covers them all: every box grows by
// s = kSlack·M on every side, M the largest |p - o| component over the whole
// scene's box (one number per ray, the same for every node).
// - The watertight triangle test (triangle_intersection.h) decides on
//   sheared vertices moved by at most ~5u·M (u = 2^-24: p - o, the shear
//   factor, its product and the subtraction each round once), and a
//   sphere's double-precision discriminant moves a grazing ray's silhouette
//   by about sqrt(ε_double) ≈ 0.2u of the distance. Woop, Benthin and Wald
//   (JCGT 2013, on BVH traversal) enlarge the boxes during traversal for
//   the same reason.
// - The t the triangle test returns is a weighted mean of the vertices'
//   sheared z, off by at most ~9u·M/|dir[kz]|; the point o + t·dir it names
//   is then off by at most 9u·M along any axis (|dir[a]| <= |dir[kz]|). A
//   sphere's t is rounded once to float, u·M at most.
// - The slab arithmetic rounds: (plane - origin), 1/direction and their
//   product carry at most γ(3) = 3u/(1 - 3u) relative error, for which
//   pbrt-v4 scales each slab's exit by 1 + 2γ(3) (Bounds3::IntersectP,
//   src/pbrt/util/vecmath.h). Here |plane - origin| <= M + s, so that is at
//   most 3u·(M + s) of distance along the axis.
// Together under 18u·M; kSlack = 32u leaves them room, and the comparisons
// need no tolerance of their own: with the boxes grown, the plain
// tNear <= tFar is conservative as it stands.
//
// A zero direction component gives 1/direction = ±inf: outside the slab the
// entry is +inf or the exit -inf (a miss), inside the slab ±inf the right
// way round; on the plane itself 0·inf is NaN, and the comparisons are
// written so a NaN constrains nothing (the ray runs in the box's face).
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

#include "ray/bounds.h"
#include "ray/ray.h"

namespace facet::ray {

// 32u: the three errors above come to under 18u·M.
inline constexpr float kSlack = 0x1p-19f;
// An absolute floor, above any denormal a flush to zero can drop from a box.
inline constexpr float kSlackFloor = 1e-30f;

// The ray as the slab test needs it, once per ray.
struct SlabRay {
  glm::vec3 inverseDirection{0.0f};
  // The origin moved by the allowance, towards +inf for the lower planes and
  // towards -inf for the upper ones: lower - (o + s) is the lower plane
  // moved out by s; rounded one float further so the move is never lost.
  glm::vec3 originForLower{0.0f}, originForUpper{0.0f};
  bool negative[3] = {false, false, false};  // direction's sign bit per axis (-0 counts): the upper plane comes first
};

// `scene` is the box around everything the ray may be tested against.
// std::nextafter(x, ±inf) for a finite x, inline (the library's is a call,
// six of them per ray): the float one step further from x in that direction.
inline float stepUp(float x) {
  if (x == 0.0f) return std::numeric_limits<float>::denorm_min();
  std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
  bits = x > 0.0f ? bits + 1 : bits - 1;
  return std::bit_cast<float>(bits);
}
inline float stepDown(float x) { return -stepUp(-x); }

inline SlabRay makeSlabRay(const Ray& ray, const Bounds& scene) {
  SlabRay r;
  float reach = 0.0f;  // M; NaN-free: canHit turned away non-finite origins and the scene box is finite
  for (int a = 0; a < 3; ++a) {
    const float low = std::fabs(scene.lower[a] - ray.origin[a]), high = std::fabs(scene.upper[a] - ray.origin[a]);
    reach = low > reach ? low : reach;
    reach = high > reach ? high : reach;
  }
  const float scaled = kSlack * reach;
  const float slack = scaled > kSlackFloor ? scaled : kSlackFloor;
  for (int a = 0; a < 3; ++a) {
    r.inverseDirection[a] = 1.0f / ray.direction[a];
    r.originForLower[a] = stepUp(ray.origin[a] + slack);
    r.originForUpper[a] = stepDown(ray.origin[a] - slack);
    r.negative[a] = std::signbit(ray.direction[a]);
  }
  return r;
}

// Whether the ray may meet the box, grown by the allowance, for some t in
// [tLow, tHigh] (closed: a hit at exactly tHigh must still be looked for),
// and where: its entry t (at least tLow), by which the traversal orders two
// children and skips one that starts beyond the nearest hit found meanwhile.
inline bool slabEntry(const glm::vec3& lower, const glm::vec3& upper, const SlabRay& r, float tLow, float tHigh, float& entry) {
  float tNear = tLow, tFar = tHigh;
  for (int a = 0; a < 3; ++a) {
    const float tLower = (lower[a] - r.originForLower[a]) * r.inverseDirection[a];
    const float tUpper = (upper[a] - r.originForUpper[a]) * r.inverseDirection[a];
    const float enter = r.negative[a] ? tUpper : tLower, exit = r.negative[a] ? tLower : tUpper;
    tNear = enter > tNear ? enter : tNear;  // a NaN leaves tNear as it is
    tFar = exit < tFar ? exit : tFar;
  }
  entry = tNear;
  return tNear <= tFar;
}

// slabEntry without the entry: the any-hit traversal's test.
inline bool slabTest(const glm::vec3& lower, const glm::vec3& upper, const SlabRay& r, float tLow, float tHigh) {
  float entry = 0.0f;
  return slabEntry(lower, upper, r, tLow, tHigh, entry);
}

}  // namespace facet::ray
