// BVH figures on a random scene of about a million triangles (a soup:
// centres uniform in a 100-unit cube, sizes from 0.05 to 1): build time with
// 1 and 2 workers, nodes, leaves, depth, bytes, and millions of rays per
// second (nearest hit and occlusion, one thread) for the test suite's mix of
// random rays. Prints; asserts nothing.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include <glm/geometric.hpp>

#include "common/thread_pool.h"
#include "ray/bvh.h"
#include "ray_test_scenes.h"

using namespace facet;
using namespace facet::ray;

namespace {

Primitives triangleSoup(int count) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> position(-50.0f, 50.0f), logSize(std::log(0.05f), std::log(1.0f));
  std::normal_distribution<float> normal;
  auto unit = [&] { return glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng))); };
  Primitives p;
  p.triangleCorners.reserve(3 * static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const glm::vec3 c(position(rng), position(rng), position(rng));
    const float size = std::exp(logSize(rng));
    p.triangleCorners.insert(p.triangleCorners.end(), {c + size * unit(), c + size * unit(), c + size * unit()});
  }
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  const int triangles = argc > 1 ? std::atoi(argv[1]) : 1000000;
  const Primitives primitives = triangleSoup(triangles);
  std::printf("%zu triangles, %zu spheres\n", primitives.triangleCount(), primitives.sphereCount());
  Bvh bvh;
  for (const int workers : {1, 2}) {
    ThreadPool pool(workers);
    bvh = Bvh(primitives, pool);
    std::printf("build, %d worker%s: %.1f ms\n", workers, workers > 1 ? "s" : "", bvh.stats().buildMilliseconds);
  }
  const BvhStats& s = bvh.stats();
  std::printf("nodes %zu, leaves %zu, max depth %d, %.1f MB (%zu bytes)\n", s.nodes, s.leaves, s.maxDepth, static_cast<double>(s.bytes) / (1 << 20), s.bytes);

  const std::vector<Ray> rays = test::randomRays(primitives, 2, 1000000);
  int hits = 0, occluded = 0;
  auto start = std::chrono::steady_clock::now();
  for (const Ray& ray : rays) {
    Hit hit;
    hits += bvh.intersect(ray, hit);
  }
  const double nearest = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  start = std::chrono::steady_clock::now();
  for (const Ray& ray : rays) occluded += bvh.occluded(ray);
  const double any = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("nearest hit: %.2f Mrays/s (%d of %zu hit); occlusion: %.2f Mrays/s (%d)\n", static_cast<double>(rays.size()) / nearest / 1e6,
              hits, rays.size(), static_cast<double>(rays.size()) / any / 1e6, occluded);
  return 0;
}
