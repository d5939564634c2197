// Building the BVH (bvh.h): binned SAH splits, the upper levels on the
// calling thread, the subtrees on the pool's workers, joined in a fixed
// order so the tree does not depend on the number of workers.
//
// Index of this file
// [SECTION] Primitive references
// [SECTION] Passes over a range (sequential, or shared by the workers)
// [SECTION] Choosing a split
// [SECTION] Subtrees and the upper levels
// [SECTION] The constructor
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <string>

#include "common/error.h"
#include "common/stopwatch.h"
#include "common/denormals.h"
#include "common/thread_pool.h"
#include "ray/bvh.h"

namespace facet::ray {
namespace {

constexpr int kBinCount = 16;
// The cost of visiting a node against testing one primitive, the SAH's
// C_trav / C_isect. pbrt-v4 takes 1/2; here a node visit tests both
// children's boxes and is, far more often than a leaf's primitives, a cache
// miss, while the triangle test is inline: facet bench --backends ray on
// sphere-1m measured primary rays at 7.2, 7.6 and 9.8 Mray/s for 0.5, 1
// and 2 (shadow rays 3.7, 3.8, 4.8), with 23% fewer nodes at 2.
constexpr double kTraversalCost = 2.0;
// A range this small or smaller becomes one worker's subtree.
constexpr std::size_t kSubtreePrimitives = 4096;
// A range at least this big is summarised and binned by all workers, in
// chunks of kChunkPrimitives.
constexpr std::size_t kParallelPassPrimitives = 1 << 16;
constexpr std::size_t kChunkPrimitives = 1 << 14;
// From this depth on, ranges split at their median centroid: each level then
// halves the count, so no leaf lies deeper than kSahDepth + 29 <= kMaxBvhDepth
// even for 2^31 primitives, and the traversal's stack has a fixed size.
constexpr int kSahDepth = 32;
static_assert(kSahDepth + 29 <= kMaxBvhDepth);

// [SECTION] Primitive references

struct Reference {
  Bounds bounds;
  glm::vec3 centroid{0.0f};  // the box's centre, halved before adding so it cannot overflow
  std::uint32_t primitive = 0;
};

// [SECTION] Passes over a range (sequential, or shared by the workers)

// What a node needs to know of its range: the box around its primitives and
// the box around their centroids.
struct Summary {
  Bounds bounds, centroids;

  void add(const Reference& r) {
    bounds.grow(r.bounds);
    centroids.grow(r.centroid);
  }
  void add(const Summary& s) {
    bounds.grow(s.bounds);
    centroids.grow(s.centroids);
  }
};

struct Bin {
  Bounds bounds;
  std::size_t count = 0;
};
using Bins = std::array<Bin, kBinCount>;

// The bin of centroid coordinate c in [low, high] (high > low): in double so
// that no extent overflows; the centroid at `high` lands in the last bin.
int binOf(float c, float low, float high) {
  const double f = (static_cast<double>(c) - low) / (static_cast<double>(high) - low);
  return std::min(static_cast<int>(f * kBinCount), kBinCount - 1);
}

void addToBins(const Reference& r, int axis, float low, float high, Bins& bins) {
  Bin& b = bins[static_cast<std::size_t>(binOf(r.centroid[axis], low, high))];
  b.bounds.grow(r.bounds);
  ++b.count;
}

void addBins(const Bins& from, Bins& to) {
  for (std::size_t b = 0; b < from.size(); ++b) {
    to[b].bounds.grow(from[b].bounds);
    to[b].count += from[b].count;
  }
}

// Calls work(worker, begin, end) on chunks of [begin, end) spread over the
// pool's workers. What each chunk gives is kept per worker and merged by the
// caller; the merges are unions and counts, exact in any order, so the result
// does not depend on which worker took which chunk.
template <class Work>
void forChunks(ThreadPool& pool, std::size_t begin, std::size_t end, Work&& work) {
  std::atomic<std::size_t> next{begin};
  pool.run([&](int worker) {
    for (;;) {
      const std::size_t b = next.fetch_add(kChunkPrimitives);
      if (b >= end) return;
      work(worker, b, std::min(end, b + kChunkPrimitives));
    }
  });
}

Summary summarise(const std::vector<Reference>& refs, std::size_t begin, std::size_t end, ThreadPool* pool) {
  Summary s;
  if (pool && end - begin >= kParallelPassPrimitives) {
    std::vector<Summary> perWorker(static_cast<std::size_t>(pool->size()));
    forChunks(*pool, begin, end, [&](int worker, std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) perWorker[static_cast<std::size_t>(worker)].add(refs[i]);
    });
    for (const Summary& w : perWorker) s.add(w);
    return s;
  }
  for (std::size_t i = begin; i < end; ++i) s.add(refs[i]);
  return s;
}

Bins bin(const std::vector<Reference>& refs, std::size_t begin, std::size_t end, int axis, float low, float high, ThreadPool* pool) {
  Bins bins;
  if (pool && end - begin >= kParallelPassPrimitives) {
    std::vector<Bins> perWorker(static_cast<std::size_t>(pool->size()));
    forChunks(*pool, begin, end, [&](int worker, std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) addToBins(refs[i], axis, low, high, perWorker[static_cast<std::size_t>(worker)]);
    });
    for (const Bins& w : perWorker) addBins(w, bins);
    return bins;
  }
  for (std::size_t i = begin; i < end; ++i) addToBins(refs[i], axis, low, high, bins);
  return bins;
}

// [SECTION] Choosing a split

// Splits [begin, end) into [begin, middle) and [middle, end), reordering
// it, and says on which axis; false when the range stays one leaf.
bool split(std::vector<Reference>& refs, std::size_t begin, std::size_t end, int depth, const Summary& s, ThreadPool* pool,
           std::size_t& middle, int& axis) {
  const std::size_t count = end - begin;
  if (count == 1) return false;
  axis = s.centroids.largestAxis();
  const float low = s.centroids.lower[axis], high = s.centroids.upper[axis];
  const int a = axis;

  // Every centroid at one point: no plane parts them, so halve the range as
  // it stands.
  if (!(high > low)) {
    if (count <= kMaxLeafPrimitives) return false;
    middle = begin + count / 2;
    return true;
  }

  // Deep down, or a box without area to weigh (all primitives on one line):
  // the median centroid, ties by primitive index.
  const double area = s.bounds.halfArea();
  if (depth >= kSahDepth || !(area > 0.0)) {
    if (count <= kMaxLeafPrimitives) return false;
    middle = begin + count / 2;
    const auto first = refs.begin() + static_cast<std::ptrdiff_t>(begin);
    std::nth_element(first, refs.begin() + static_cast<std::ptrdiff_t>(middle), refs.begin() + static_cast<std::ptrdiff_t>(end),
                     [a](const Reference& x, const Reference& y) {
                       return x.centroid[a] < y.centroid[a] || (x.centroid[a] == y.centroid[a] && x.primitive < y.primitive);
                     });
    return true;
  }

  // The SAH: splitting after bin k costs
  //   C_trav + (N_left·A_left + N_right·A_right) / A_node
  // in units of one primitive test; a leaf costs N.
  const Bins bins = bin(refs, begin, end, axis, low, high, pool);
  std::array<double, kBinCount> leftCost{};  // N_left·A_left for a split after bin k
  Bounds left;
  std::size_t leftCount = 0;
  for (std::size_t k = 0; k + 1 < kBinCount; ++k) {
    left.grow(bins[k].bounds);
    leftCount += bins[k].count;
    leftCost[k] = static_cast<double>(leftCount) * left.halfArea();
  }
  Bounds right;
  std::size_t rightCount = 0;
  double bestCost = 0.0;
  int bestBin = -1;
  for (std::size_t k = kBinCount - 1; k > 0; --k) {
    right.grow(bins[k].bounds);
    rightCount += bins[k].count;
    if (rightCount == 0 || rightCount == count) continue;  // one side empty
    const double cost = kTraversalCost + (leftCost[k - 1] + static_cast<double>(rightCount) * right.halfArea()) / area;
    if (bestBin < 0 || cost <= bestCost) bestCost = cost, bestBin = static_cast<int>(k - 1);  // <=: the lowest bin on a tie
  }
  // The centroids at `low` and `high` fill the first and last bins, so some
  // split has both sides; if none had, halving keeps the build going.
  if (bestBin < 0) {
    if (count <= kMaxLeafPrimitives) return false;
    middle = begin + count / 2;
    return true;
  }
  if (count <= kMaxLeafPrimitives && !(bestCost < static_cast<double>(count))) return false;
  const auto mid = std::partition(refs.begin() + static_cast<std::ptrdiff_t>(begin), refs.begin() + static_cast<std::ptrdiff_t>(end),
                                  [&](const Reference& r) { return binOf(r.centroid[a], low, high) <= bestBin; });
  middle = static_cast<std::size_t>(mid - refs.begin());
  return true;
}

// [SECTION] Subtrees and the upper levels

BvhNode makeNode(const Bounds& bounds) {
  BvhNode n;
  n.lower = bounds.lower;
  n.upper = bounds.upper;
  return n;
}

// One worker's subtree, depth-first, its second-child offsets counted from
// its own first node; its slots are positions in the shared reference array.
struct Subtree {
  std::size_t begin = 0, end = 0;
  int depth = 0;  // of its root in the whole tree
  std::vector<BvhNode> nodes;
  std::size_t leaves = 0;
  int maxDepth = 0;
};

void buildSubtree(std::vector<Reference>& refs, std::size_t begin, std::size_t end, int depth, Subtree& out) {
  const Summary s = summarise(refs, begin, end, nullptr);
  const std::size_t index = out.nodes.size();
  out.nodes.push_back(makeNode(s.bounds));
  out.maxDepth = std::max(out.maxDepth, depth);
  std::size_t middle = 0;
  int axis = 0;
  if (!split(refs, begin, end, depth, s, nullptr, middle, axis)) {
    out.nodes[index].offset = static_cast<std::uint32_t>(begin);
    out.nodes[index].count = static_cast<std::uint16_t>(end - begin);
    ++out.leaves;
    return;
  }
  out.nodes[index].axis = static_cast<std::uint8_t>(axis);
  buildSubtree(refs, begin, middle, depth + 1, out);
  out.nodes[index].offset = static_cast<std::uint32_t>(out.nodes.size());
  buildSubtree(refs, middle, end, depth + 1, out);
}

// The levels above the subtrees: an interior node, or a subtree's place.
struct UpperNode {
  Bounds bounds;
  int axis = 0;
  std::size_t left = 0, right = 0;  // UpperNode indices
  std::size_t subtree = 0;
  bool isSubtree = false;
};

struct UpperTree {
  std::vector<UpperNode> nodes;
  std::vector<Subtree> subtrees;
};

std::size_t buildUpper(std::vector<Reference>& refs, std::size_t begin, std::size_t end, int depth, ThreadPool& pool, UpperTree& tree) {
  const std::size_t index = tree.nodes.size();
  tree.nodes.emplace_back();
  if (end - begin <= kSubtreePrimitives) {
    tree.nodes[index].isSubtree = true;
    tree.nodes[index].subtree = tree.subtrees.size();
    Subtree& s = tree.subtrees.emplace_back();
    s.begin = begin, s.end = end, s.depth = depth;
    return index;
  }
  const Summary s = summarise(refs, begin, end, &pool);
  std::size_t middle = 0;
  int axis = 0;
  split(refs, begin, end, depth, s, &pool, middle, axis);  // always splits: more than kMaxLeafPrimitives
  tree.nodes[index].bounds = s.bounds;
  tree.nodes[index].axis = axis;
  const std::size_t left = buildUpper(refs, begin, middle, depth + 1, pool, tree);
  const std::size_t right = buildUpper(refs, middle, end, depth + 1, pool, tree);
  tree.nodes[index].left = left, tree.nodes[index].right = right;
  return index;
}

// Depth-first: each upper node, then its first child's nodes, then its second's.
void join(const UpperTree& tree, std::size_t upper, std::vector<BvhNode>& out) {
  const UpperNode& n = tree.nodes[upper];
  if (n.isSubtree) {
    const auto base = static_cast<std::uint32_t>(out.size());
    for (BvhNode node : tree.subtrees[n.subtree].nodes) {
      if (node.count == 0) node.offset += base;
      out.push_back(node);
    }
    return;
  }
  const std::size_t index = out.size();
  out.push_back(makeNode(n.bounds));
  out[index].axis = static_cast<std::uint8_t>(n.axis);
  join(tree, n.left, out);
  out[index].offset = static_cast<std::uint32_t>(out.size());
  join(tree, n.right, out);
}

}  // namespace

// [SECTION] The constructor

Bvh::Bvh(const Primitives& primitives, ThreadPool& pool) {
  const auto start = std::chrono::steady_clock::now();
  checkPrimitiveCounts(primitives.triangleCorners.size(), primitives.spheres.size());
  // Every step of the build in one floating-point mode, the workers' (they
  // flush denormals, thread_pool.h), whichever thread runs it.
  const FlushDenormals flush;
  const std::size_t count = primitives.count();
  triangleCount_ = static_cast<std::uint32_t>(primitives.triangleCount());

  // Each primitive's box and centroid, then the finite ones in index order.
  std::vector<Reference> all(count);
  std::vector<unsigned char> finite(count);
  forChunks(pool, 0, count, [&](int, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      Reference& r = all[i];
      r.primitive = static_cast<std::uint32_t>(i);
      finite[i] = primitiveBounds(primitives, r.primitive, r.bounds);
      r.centroid = 0.5f * r.bounds.lower + 0.5f * r.bounds.upper;
    }
  });
  std::vector<Reference> refs;
  refs.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
    if (finite[i]) refs.push_back(all[i]);
  std::vector<Reference>().swap(all);
  stats_.primitives = refs.size();
  stats_.skipped = count - refs.size();

  if (!refs.empty()) {
    UpperTree tree;
    buildUpper(refs, 0, refs.size(), 0, pool, tree);
    std::atomic<std::size_t> next{0};
    pool.run([&](int) {
      for (;;) {
        const std::size_t k = next.fetch_add(1);
        if (k >= tree.subtrees.size()) return;
        Subtree& s = tree.subtrees[k];
        buildSubtree(refs, s.begin, s.end, s.depth, s);
      }
    });
    std::size_t total = 0;
    for (const Subtree& s : tree.subtrees) {
      total += s.nodes.size();
      stats_.leaves += s.leaves;
      stats_.maxDepth = std::max(stats_.maxDepth, s.maxDepth);
    }
    nodes_.reserve(total + tree.nodes.size() - tree.subtrees.size());
    join(tree, 0, nodes_);
    if (stats_.maxDepth > kMaxBvhDepth) throw Error("ray tracing: the BVH is " + std::to_string(stats_.maxDepth) + " levels deep");

    slots_.resize(refs.size());
    forChunks(pool, 0, refs.size(), [&](int, std::size_t b, std::size_t e) {
      for (std::size_t k = b; k < e; ++k) {
        Slot& slot = slots_[k];
        const std::uint32_t p = refs[k].primitive;
        slot.primitive = p;
        if (p < triangleCount_) {
          const glm::vec3* corners = &primitives.triangleCorners[3 * std::size_t{p}];
          slot.a = corners[0], slot.b = corners[1], slot.c = corners[2];
        } else {
          const glm::vec4 sphere = primitives.spheres[p - triangleCount_];
          slot.a = glm::vec3(sphere);
          slot.b = glm::vec3(sphere.w, 0.0f, 0.0f);
        }
      }
    });
  }

  stats_.nodes = nodes_.size();
  stats_.bytes = nodes_.size() * sizeof(BvhNode) + slots_.size() * sizeof(Slot);
  stats_.buildMilliseconds = millisecondsSince(start);
}

}  // namespace facet::ray
