// The BVH against brute force: the same nearest hit bit for bit and the same
// occlusion answer on seeded random scenes full of awkward cases, the tie
// rule, the same tree for any number of workers, the node layout and its
// invariants, the depth limit, degenerate and oversized inputs, and a closed
// mesh that no ray through the tree leaks out of.
#include <algorithm>
#include <cstring>
#include <limits>
#include <random>
#include <set>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "common/error.h"
#include "common/thread_pool.h"
#include "ray/brute_force.h"
#include "ray/bvh.h"
#include "ray_test_scenes.h"
#include "vocabulary/limits.h"

using namespace facet;
using namespace facet::ray;

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

struct Agreement {
  int rays = 0, hits = 0, nearestDiffer = 0, occlusionDiffers = 0;
};

Agreement compare(const Bvh& bvh, const Primitives& primitives, const std::vector<Ray>& rays) {
  Agreement a;
  for (const Ray& ray : rays) {
    ++a.rays;
    Hit fromTree, fromAll;
    const bool treeHit = bvh.intersect(ray, fromTree), allHit = intersectBruteForce(primitives, ray, fromAll);
    if (treeHit != allHit || (treeHit && !test::sameHit(fromTree, fromAll))) ++a.nearestDiffer;
    if (bvh.occluded(ray) != occludedBruteForce(primitives, ray)) ++a.occlusionDiffers;
    a.hits += allHit;
  }
  return a;
}

const char* name(test::SceneKind kind) {
  switch (kind) {
    case test::SceneKind::Scattered: return "scattered";
    case test::SceneKind::Clustered: return "clustered";
    case test::SceneKind::Coincident: return "coincident";
    case test::SceneKind::Slivers: return "slivers";
    case test::SceneKind::Broken: return "broken";
  }
  return "?";
}

// Walks the tree from node `index`: checks what every node promises and
// collects the slots its leaves hold, in order.
void walk(const Bvh& bvh, std::uint32_t index, int depth, std::vector<std::uint32_t>& slots, int& maxDepth, std::size_t& leaves) {
  const std::vector<BvhNode>& nodes = bvh.nodes();
  REQUIRE(index < nodes.size());
  const BvhNode& n = nodes[index];
  maxDepth = std::max(maxDepth, depth);
  CHECK(n.lower.x <= n.upper.x);
  CHECK(n.lower.y <= n.upper.y);
  CHECK(n.lower.z <= n.upper.z);
  if (n.count > 0) {
    CHECK(n.count <= kMaxLeafPrimitives);
    ++leaves;
    for (std::uint32_t k = n.offset; k < n.offset + n.count; ++k) slots.push_back(k);
    return;
  }
  const std::uint32_t first = index + 1, second = n.offset;
  REQUIRE(second > first);  // depth-first: the first child follows, the second after its subtree
  for (const std::uint32_t child : {first, second}) {
    const BvhNode& c = nodes[child];
    for (int a = 0; a < 3; ++a) {
      CHECK(c.lower[a] >= n.lower[a]);
      CHECK(c.upper[a] <= n.upper[a]);
    }
  }
  walk(bvh, first, depth + 1, slots, maxDepth, leaves);
  walk(bvh, second, depth + 1, slots, maxDepth, leaves);
}

// The leaf that holds slot k: its box must hold the primitive's.
const BvhNode* leafOf(const Bvh& bvh, std::uint32_t slot) {
  for (const BvhNode& n : bvh.nodes())
    if (n.count > 0 && slot >= n.offset && slot < n.offset + n.count) return &n;
  return nullptr;
}

}  // namespace

TEST_CASE("bvh: the nearest hit is brute force's, bit for bit, and occlusion agrees, on random scenes") {
  ThreadPool pool(2);
  const test::SceneKind kinds[] = {test::SceneKind::Scattered, test::SceneKind::Clustered, test::SceneKind::Coincident,
                                   test::SceneKind::Slivers, test::SceneKind::Broken};
  for (const test::SceneKind kind : kinds)
    for (std::uint32_t seed = 1; seed <= 2; ++seed) {
      const Primitives primitives = test::randomScene(kind, 100 * seed + static_cast<std::uint32_t>(kind), 1500);
      const Bvh bvh(primitives, pool);
      const Agreement a = compare(bvh, primitives, test::randomRays(primitives, seed, 2500));
      CAPTURE(name(kind));
      CAPTURE(seed);
      CHECK(a.nearestDiffer == 0);
      CHECK(a.occlusionDiffers == 0);
      CHECK(a.hits > a.rays / 10);  // the rays find things: the comparison is not of misses
    }
}

TEST_CASE("bvh: at exactly the same t the smaller primitive index wins, whichever child the traversal visits first") {
  // The same triangle and the same sphere at many indices, among others:
  // the copies' centroids coincide, so they are halved into different
  // leaves, and rays along +x and -x visit those leaves in opposite orders.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-4.0f, 4.0f);
  Primitives primitives;
  const glm::vec3 a(0.1f, -1.0f, -1.0f), b(0.1f, 1.5f, -1.0f), c(0.1f, 0.0f, 1.7f);
  std::vector<std::uint32_t> copies;
  for (std::uint32_t i = 0; i < 400; ++i) {
    if (i % 13 == 5) {
      copies.push_back(i);
      primitives.triangleCorners.insert(primitives.triangleCorners.end(), {a, b, c});
    } else {
      const glm::vec3 p(u(rng) + 10.0f, u(rng), u(rng));  // away from the copies
      primitives.triangleCorners.insert(primitives.triangleCorners.end(), {p, p + glm::vec3(0.3f, 0, 0), p + glm::vec3(0, 0.3f, 0.1f)});
    }
  }
  const auto triangles = static_cast<std::uint32_t>(primitives.triangleCount());
  for (int i = 0; i < 20; ++i) primitives.spheres.emplace_back(-5.0f, 0.25f, 0.5f, 0.75f);
  ThreadPool pool(1);
  const Bvh bvh(primitives, pool);
  for (const float dx : {1.0f, -1.0f}) {
    const Ray ray{{-4.0f * dx + 0.1f, 0.2f, 0.1f}, {dx, 0.0f, 0.0f}};
    Hit fromTree, fromAll;
    REQUIRE(bvh.intersect(ray, fromTree));
    REQUIRE(intersectBruteForce(primitives, ray, fromAll));
    CHECK(fromTree.primitive == copies.front());
    CHECK(test::sameHit(fromTree, fromAll));
    const Ray toSpheres{{-5.0f + 3.0f * dx, 0.25f, 0.5f}, {-dx, 0.0f, 0.0f}, 0.0f, 2.9f};
    REQUIRE(bvh.intersect(toSpheres, fromTree));
    REQUIRE(intersectBruteForce(primitives, toSpheres, fromAll));
    CHECK(fromTree.primitive == triangles);  // the first sphere
    CHECK(test::sameHit(fromTree, fromAll));
  }
}

TEST_CASE("bvh: the same nodes and the same primitive order with 1, 2 and 3 workers") {
  Primitives primitives = test::randomScene(test::SceneKind::Clustered, 11, 90000);
  const Primitives more = test::randomScene(test::SceneKind::Scattered, 12, 60000);
  primitives.triangleCorners.insert(primitives.triangleCorners.end(), more.triangleCorners.begin(), more.triangleCorners.end());
  primitives.spheres.insert(primitives.spheres.end(), more.spheres.begin(), more.spheres.end());
  std::vector<Bvh> trees;
  for (const int workers : {1, 2, 3}) {
    ThreadPool pool(workers);
    trees.emplace_back(primitives, pool);
  }
  for (std::size_t k = 1; k < trees.size(); ++k) {
    CAPTURE(k + 1);
    const std::vector<BvhNode>& expected = trees[0].nodes();
    const std::vector<BvhNode>& actual = trees[k].nodes();
    REQUIRE(actual.size() == expected.size());
    CHECK(std::memcmp(actual.data(), expected.data(), actual.size() * sizeof(BvhNode)) == 0);
    CHECK(trees[k].primitiveOrder() == trees[0].primitiveOrder());
    CHECK(trees[k].stats().maxDepth == trees[0].stats().maxDepth);
    CHECK(trees[k].stats().leaves == trees[0].stats().leaves);
  }
}

TEST_CASE("bvh: the nodes are 32 bytes in depth-first order, each box holds its children and its primitives, each finite primitive is in one leaf") {
  static_assert(sizeof(BvhNode) == 32);
  ThreadPool pool(2);
  for (const test::SceneKind kind : {test::SceneKind::Scattered, test::SceneKind::Coincident, test::SceneKind::Broken}) {
    CAPTURE(name(kind));
    const Primitives primitives = test::randomScene(kind, 5, 3000);
    const Bvh bvh(primitives, pool);
    std::vector<std::uint32_t> slots;
    int maxDepth = 0;
    std::size_t leaves = 0;
    walk(bvh, 0, 0, slots, maxDepth, leaves);
    // The leaves, left to right, hold slots 0, 1, 2, ... once each.
    const std::vector<std::uint32_t> order = bvh.primitiveOrder();
    REQUIRE(slots.size() == order.size());
    for (std::uint32_t k = 0; k < slots.size(); ++k) CHECK(slots[k] == k);
    // Every primitive with finite bounds once, none without.
    std::set<std::uint32_t> expected, actual(order.begin(), order.end());
    for (std::uint32_t i = 0; i < primitives.count(); ++i) {
      Bounds b;
      if (primitiveBounds(primitives, i, b)) expected.insert(i);
    }
    CHECK(actual == expected);
    CHECK(actual.size() == order.size());
    for (std::uint32_t k = 0; k < order.size(); k += 7) {  // a leaf's box holds its primitives' boxes
      const BvhNode* leaf = leafOf(bvh, k);
      REQUIRE(leaf != nullptr);
      Bounds b;
      REQUIRE(primitiveBounds(primitives, order[k], b));
      for (int a = 0; a < 3; ++a) {
        CHECK(leaf->lower[a] <= b.lower[a]);
        CHECK(leaf->upper[a] >= b.upper[a]);
      }
    }
    const BvhStats& stats = bvh.stats();
    CHECK(stats.nodes == bvh.nodes().size());
    CHECK(stats.leaves == leaves);
    CHECK(stats.nodes == 2 * stats.leaves - 1);
    CHECK(stats.maxDepth == maxDepth);
    CHECK(stats.primitives == order.size());
    CHECK(stats.primitives + stats.skipped == primitives.count());
    CHECK(stats.bytes >= stats.nodes * sizeof(BvhNode));
    CHECK(stats.buildMilliseconds >= 0.0);
  }
}

TEST_CASE("bvh: a scene that makes the SAH peel off a few primitives per level goes past depth 32, stays within the limit and still agrees") {
  // Spheres at x = 1.25^k, radius x/4: a split on 16 even bins over a range
  // of 29 orders of magnitude cuts off the few largest spheres, so the SAH
  // alone goes about 40 deep; from depth 32 on the median rule halves.
  Primitives primitives;
  float x = 1.0f;
  for (int k = 0; k < 300; ++k, x *= 1.25f) primitives.spheres.emplace_back(x, 0.0f, 0.0f, 0.25f * x);
  ThreadPool pool(2);
  const Bvh bvh(primitives, pool);
  CHECK(bvh.stats().maxDepth <= kMaxBvhDepth);
  CHECK(bvh.stats().maxDepth > 32);  // the case is the one it claims: the SAH went deep
  std::vector<Ray> rays;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const float at = std::pow(1.25f, 300.0f * (u(rng) + 1.0f) / 2.0f);
    rays.push_back(Ray{{at, 0.3f * at * u(rng), -at}, {u(rng), u(rng), 1.0f}});
  }
  const Agreement a = compare(bvh, primitives, rays);
  CHECK(a.nearestDiffer == 0);
  CHECK(a.occlusionDiffers == 0);
  CHECK(a.hits > 0);
}

TEST_CASE("bvh: no primitives, or only broken ones, hit nothing") {
  ThreadPool pool(2);
  const Ray ray{{0, 0, 0}, {0, 0, -1}};
  Hit hit;
  const Bvh none;
  CHECK_FALSE(none.intersect(ray, hit));
  CHECK_FALSE(none.occluded(ray));
  const Bvh empty(Primitives{}, pool);
  CHECK(empty.nodes().empty());
  CHECK_FALSE(empty.intersect(ray, hit));
  CHECK_FALSE(empty.occluded(ray));
  Primitives broken;
  broken.triangleCorners = {{kNaN, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, -1}, {kInfinity, 0, -1}, {0, 1, -1}};
  broken.spheres = {{0, 0, -3, kNaN}, {0, 0, -kInfinity, 1}};
  const Bvh bvh(broken, pool);
  CHECK(bvh.nodes().empty());
  CHECK(bvh.stats().skipped == 4);
  CHECK_FALSE(bvh.intersect(ray, hit));
  CHECK_FALSE(intersectBruteForce(broken, ray, hit));
  CHECK_FALSE(occludedBruteForce(broken, ray));
}

TEST_CASE("bvh: counts beyond the node format, and corners that are not whole triangles, are refused with facet::Error") {
  const std::size_t most = kMaxTracedPrimitives;
  CHECK_NOTHROW(checkPrimitiveCounts(3 * most, 0));
  CHECK_NOTHROW(checkPrimitiveCounts(3 * (most - 5), 5));
  CHECK_THROWS_AS(checkPrimitiveCounts(3 * (most + 1), 0), Error);
  CHECK_THROWS_AS(checkPrimitiveCounts(3 * most, 1), Error);
  CHECK_THROWS_AS(checkPrimitiveCounts(0, most + 1), Error);
  CHECK_THROWS_AS(checkPrimitiveCounts(3 * most, std::numeric_limits<std::size_t>::max()), Error);
  Primitives partial;
  partial.triangleCorners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  ThreadPool pool(1);
  CHECK_THROWS_AS(Bvh(partial, pool), Error);
  Hit hit;
  CHECK_THROWS_AS(intersectBruteForce(partial, Ray{{0, 0, 0}, {0, 0, 1}}, hit), Error);
}

TEST_CASE("bvh: rays from inside a closed mesh never leak through the tree") {
  ThreadPool pool(2);
  for (std::uint32_t seed = 4; seed <= 5; ++seed) {
    const test::ClosedMesh mesh = test::icosphere(4, seed);
    const Bvh bvh(mesh.primitives, pool);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    auto inside = [&] {
      for (;;) {
        const glm::vec3 p(unit(rng), unit(rng), unit(rng));
        if (glm::length(p) < 1.0f) return mesh.centre + 0.9f * mesh.inradius * p;
      }
    };
    int rays = 0, leaks = 0, unoccluded = 0;
    auto shoot = [&](const Ray& ray) {
      Hit hit;
      ++rays;
      leaks += !bvh.intersect(ray, hit);
      unoccluded += !bvh.occluded(ray);
    };
    for (const glm::vec3& v : mesh.vertices) {
      const glm::vec3 o = inside();
      shoot(Ray{o, v - o});
    }
    for (const auto& [a, b] : mesh.edges) {
      const glm::vec3 o = inside();
      shoot(Ray{o, 0.5f * (mesh.vertices[a] + mesh.vertices[b]) - o});
    }
    for (int k = 0; k < 5000; ++k) shoot(Ray{inside(), glm::vec3(unit(rng), unit(rng), unit(rng))});
    CAPTURE(seed);
    CHECK(rays > 15000);
    CHECK(leaks == 0);
    CHECK(unoccluded == 0);
  }
}
