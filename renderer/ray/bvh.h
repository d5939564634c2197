#pragma once
// The bounding volume hierarchy of the ray-tracing backend: the course's
// hierarchical bounding boxes over triangles and spheres (primitives.h).
//
// Built top-down with the surface area heuristic over binned centroids
// (MacDonald and Booth, "Heuristics for Ray Tracing Using Space
// Subdivision", 1990; binning as in Wald, "On fast Construction of SAH-based
// Bounding Volume Hierarchies", 2007; pbrt-v4 src/pbrt/cpu/aggregates.cpp
// builds the same way). The upper levels are split on the calling thread
// with the large passes shared by the pool's workers, then the pool's
// workers build the subtrees, each into its own array, and the arrays are
// joined in a fixed order: the same nodes and the same primitive order for
// any number of workers (bvh_build.cpp).
//
// Traversal finds the nearest hit by nearer() (ray.h), the near child first,
// with a slab test that never misses a box whose primitives would be hit
// (slab_test.h), so intersect() returns exactly what intersectBruteForce()
// returns (brute_force.h).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "common/function_ref.h"
#include "ray/primitives.h"
#include "ray/ray.h"

namespace facet {
class ThreadPool;
}

namespace facet::ray {

struct WatertightRay;

inline constexpr int kMaxLeafPrimitives = 4;  // a leaf holds 1 to 4 primitives
inline constexpr int kMaxBvhDepth = 63;       // the build keeps every node's depth (root 0) at most this

// One node of the tree, in depth-first order: an interior node's first child
// is the node after it and its second child is nodes()[offset]; a leaf holds
// the primitives of slots offset .. offset + count - 1. 32 bytes, as
// pbrt-v4's LinearBVHNode.
struct BvhNode {
  glm::vec3 lower{0.0f};      // world space
  std::uint32_t offset = 0;   // interior: the second child; leaf: the first slot
  glm::vec3 upper{0.0f};      // world space
  std::uint16_t count = 0;    // a leaf's primitives; 0 for an interior node
  std::uint8_t axis = 0;      // interior: the axis the split was on
  std::uint8_t padding = 0;
};
static_assert(sizeof(BvhNode) == 32, "BvhNode is two 16-byte halves");

struct BvhStats {
  std::size_t primitives = 0;  // in the tree
  std::size_t skipped = 0;     // left out: their bounds are not finite (primitives.h)
  std::size_t nodes = 0, leaves = 0;
  int maxDepth = 0;            // the root's depth is 0
  std::size_t bytes = 0;       // the nodes and the leaf-ordered primitive copies
  double buildMilliseconds = 0.0;
};

class Bvh {
 public:
  Bvh() = default;  // holds nothing, hits nothing

  // Builds over a copy of the primitives with the pool's workers. Throws
  // facet::Error when the counts overflow the node format
  // (checkPrimitiveCounts).
  Bvh(const Primitives& primitives, ThreadPool& pool);

  // The nearest hit in (tMin, tMax), by nearer(); false when none.
  bool intersect(const Ray& ray, Hit& hit) const;
  // The nearest hit in (tMin, tMax) that `accept` takes, by nearer(): a
  // culled back face or what an alpha mask discards is looked through.
  bool intersect(const Ray& ray, Hit& hit, FunctionRef<bool(const Hit&)> accept) const;
  // Whether anything is hit in (tMin, tMax); stops at the first hit found.
  bool occluded(const Ray& ray) const;
  // Every hit in (tMin, tMax), each primitive once, in no order, until
  // `visit` returns true: shadow rays through transmissive surfaces, depth complexity.
  void forEachHit(const Ray& ray, FunctionRef<bool(const Hit&)> visit) const;

  const std::vector<BvhNode>& nodes() const { return nodes_; }
  // The primitive index of every slot, in leaf order.
  std::vector<std::uint32_t> primitiveOrder() const;
  const BvhStats& stats() const { return stats_; }

 private:
  // A primitive copied into leaf order, so a leaf reads one stretch of
  // memory: a triangle's three corners, or a sphere's centre in a and its
  // radius in b.x.
  struct Slot {
    glm::vec3 a{0.0f}, b{0.0f}, c{0.0f};  // world space
    std::uint32_t primitive = 0;
  };

  bool intersectSlot(const Slot& slot, const Ray& ray, const WatertightRay& watertight, Hit& hit) const;
  // The traversals, for any filter (bvh.cpp instantiates them).
  template <class Accept>
  bool nearest(const Ray& ray, Hit& hit, const Accept& accept) const;
  template <class Visit>
  bool anyHit(const Ray& ray, const Visit& visit) const;

  std::vector<BvhNode> nodes_;
  std::vector<Slot> slots_;
  std::uint32_t triangleCount_ = 0;  // slots with a smaller primitive index are triangles
  BvhStats stats_;
};

}  // namespace facet::ray
