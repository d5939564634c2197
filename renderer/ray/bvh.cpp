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
  Hit closest;
  bool found = false;
  std::uint32_t stack[kStackSize];
  int size = 0;
  std::uint32_t node = 0;
  for (;;) {
    const BvhNode& n = nodes_[node];
    if (slabTest(n.lower, n.upper, slab, ray.tMin, tHigh)) {
      if (n.count == 0) {
        // The near child first: on a negative direction along the split
        // axis, the second (upper) child comes first.
        if (slab.negative[n.axis]) {
          stack[size++] = node + 1;
          node = n.offset;
        } else {
          stack[size++] = n.offset;
          node = node + 1;
        }
        continue;
      }
      for (std::uint32_t k = n.offset; k < n.offset + n.count; ++k) {
        Hit h;
        if (intersectSlot(slots_[k], ray, watertight, h) && (!found || nearer(h, closest)) && accept(h)) {
          closest = h;
          found = true;
          tHigh = closest.t;
        }
      }
    }
    if (size == 0) break;
    node = stack[--size];
  }
  if (found) hit = closest;
  return found;
}

bool Bvh::intersect(const Ray& ray, Hit& hit) const {
  return nearest(ray, hit, [](const Hit&) { return true; });
}

bool Bvh::intersect(const Ray& ray, Hit& hit, cpu::FunctionRef<bool(const Hit&)> accept) const { return nearest(ray, hit, accept); }

template <class Visit>
bool Bvh::anyHit(const Ray& ray, const Visit& visit) const {
  if (nodes_.empty() || !canHit(ray)) return false;
  const WatertightRay watertight = makeWatertightRay(ray);
  const SlabRay slab = makeSlabRay(ray, Bounds{nodes_[0].lower, nodes_[0].upper});
  std::uint32_t stack[kStackSize];
  int size = 0;
  std::uint32_t node = 0;
  for (;;) {
    const BvhNode& n = nodes_[node];
    if (slabTest(n.lower, n.upper, slab, ray.tMin, ray.tMax)) {
      if (n.count == 0) {
        const bool upperFirst = slab.negative[n.axis];
        stack[size++] = upperFirst ? node + 1 : n.offset;
        node = upperFirst ? n.offset : node + 1;
        continue;
      }
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

void Bvh::forEachHit(const Ray& ray, cpu::FunctionRef<bool(const Hit&)> visit) const { anyHit(ray, visit); }

}  // namespace facet::ray
