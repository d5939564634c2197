// Traversing the BVH (bvh.h): depth-first with a fixed stack, the near child
// first, every box through the conservative slab test (slab_test.h).
#include "ray/bvh.h"

#include "ray/slab_test.h"
#include "ray/sphere_intersection.h"
#include "ray/triangle_intersection.h"

namespace facet::ray {
namespace {

// A path from the root holds at most kMaxBvhDepth nodes besides the root,
// and each pushes at most one sibling.
constexpr int kStackSize = kMaxBvhDepth + 1;

}  // namespace

std::vector<std::uint32_t> Bvh::primitiveOrder() const {
  std::vector<std::uint32_t> order(slots_.size());
  for (std::size_t k = 0; k < slots_.size(); ++k) order[k] = slots_[k].primitive;
  return order;
}

bool Bvh::intersectSlot(const Slot& slot, const Ray& ray, const WatertightRay& watertight, Hit& hit) const {
  hit.primitive = slot.primitive;
  if (slot.primitive < triangleCount_) {
    TriangleHit h;
    if (!intersectTriangle(watertight, slot.a, slot.b, slot.c, h)) return false;
    hit.t = h.t, hit.u = h.u, hit.v = h.v;
    return true;
  }
  hit.u = hit.v = 0.0f;
  return intersectSphere(ray, slot.a, slot.b.x, hit.t);
}

template <class Accept>
bool Bvh::nearest(const Ray& ray, Hit& hit, const Accept& accept) const {
  if (nodes_.empty() || !canHit(ray)) return false;
  const WatertightRay watertight = makeWatertightRay(ray);
  const SlabRay slab = makeSlabRay(ray, Bounds{nodes_[0].lower, nodes_[0].upper});
  float tHigh = ray.tMax;  // then the nearest hit so far: a tie at its t must still be looked for
  float entry = 0.0f;
  if (!slabEntry(nodes_[0].lower, nodes_[0].upper, slab, ray.tMin, tHigh, entry)) return false;
  Hit closest;
  bool found = false;
  // Each interior node tests both children's boxes: the nearer one (by entry t) is visited
  // next, the other kept with its entry t and skipped when it starts beyond the nearest hit.
  struct Pending {
    std::uint32_t node;
    float entry;
  };
  Pending stack[kStackSize];
  int size = 0;
  std::uint32_t node = 0;
  for (;;) {
    const BvhNode& n = nodes_[node];
    if (n.count == 0) {
      const std::uint32_t first = node + 1, second = n.offset;
      float tFirst = 0.0f, tSecond = 0.0f;
      const bool hitFirst = slabEntry(nodes_[first].lower, nodes_[first].upper, slab, ray.tMin, tHigh, tFirst);
      const bool hitSecond = slabEntry(nodes_[second].lower, nodes_[second].upper, slab, ray.tMin, tHigh, tSecond);
      if (hitFirst && hitSecond) {
        const bool secondFirst = tSecond < tFirst;
        stack[size++] = secondFirst ? Pending{first, tFirst} : Pending{second, tSecond};
        node = secondFirst ? second : first;
        continue;
      }
      if (hitFirst || hitSecond) {
        node = hitFirst ? first : second;
        continue;
      }
    } else {
      for (std::uint32_t k = n.offset; k < n.offset + n.count; ++k) {
        Hit h;
        if (intersectSlot(slots_[k], ray, watertight, h) && (!found || nearer(h, closest)) && accept(h)) {
          closest = h;
          found = true;
          tHigh = closest.t;
        }
      }
    }
    while (size > 0 && stack[size - 1].entry > tHigh) --size;  // boxes that start beyond the nearest hit
    if (size == 0) break;
    node = stack[--size].node;
  }
  if (found) hit = closest;
  return found;
}

bool Bvh::intersect(const Ray& ray, Hit& hit) const {
  return nearest(ray, hit, [](const Hit&) { return true; });
}

bool Bvh::intersect(const Ray& ray, Hit& hit, FunctionRef<bool(const Hit&)> accept) const { return nearest(ray, hit, accept); }

template <class Visit>
bool Bvh::anyHit(const Ray& ray, const Visit& visit) const {
  if (nodes_.empty() || !canHit(ray)) return false;
  const WatertightRay watertight = makeWatertightRay(ray);
  const SlabRay slab = makeSlabRay(ray, Bounds{nodes_[0].lower, nodes_[0].upper});
  if (!slabTest(nodes_[0].lower, nodes_[0].upper, slab, ray.tMin, ray.tMax)) return false;
  std::uint32_t stack[kStackSize];
  int size = 0;
  std::uint32_t node = 0;
  for (;;) {
    const BvhNode& n = nodes_[node];
    if (n.count == 0) {
      // Both children's boxes tested here; the one on the ray's side of the split first.
      const bool upperFirst = slab.negative[n.axis];
      const std::uint32_t near = upperFirst ? n.offset : node + 1, far = upperFirst ? node + 1 : n.offset;
      const bool hitNear = slabTest(nodes_[near].lower, nodes_[near].upper, slab, ray.tMin, ray.tMax);
      const bool hitFar = slabTest(nodes_[far].lower, nodes_[far].upper, slab, ray.tMin, ray.tMax);
      if (hitNear || hitFar) {
        if (hitNear && hitFar) stack[size++] = far;
        node = hitNear ? near : far;
        continue;
      }
    } else {
      for (std::uint32_t k = n.offset; k < n.offset + n.count; ++k) {
        Hit h;
        if (intersectSlot(slots_[k], ray, watertight, h) && visit(h)) return true;
      }
    }
    if (size == 0) return false;
    node = stack[--size];
  }
}

bool Bvh::occluded(const Ray& ray) const {
  return anyHit(ray, [](const Hit&) { return true; });
}

void Bvh::forEachHit(const Ray& ray, FunctionRef<bool(const Hit&)> visit) const { anyHit(ray, visit); }

}  // namespace facet::ray
