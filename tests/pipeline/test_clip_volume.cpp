// Whole-instance culling (pipeline/clip_volume.h): a box said to miss the
// clip volume has no point inside it, and boxes beside each plane, across a
// corner or behind the eye are told apart.
#include <doctest/doctest.h>

#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline/clip_volume.h"

namespace facet {
namespace {

Bounds box(glm::vec3 lo, glm::vec3 hi) {
  Bounds b;
  b.include(lo);
  b.include(hi);
  return b;
}

bool insideClip(const glm::vec4& c) { return -c.w <= c.x && c.x <= c.w && -c.w <= c.y && c.y <= c.w && 0.0f <= c.z && c.z <= c.w; }

TEST_CASE("Clip volume: a box beyond one plane misses, one across the volume or entering it further away does not") {
  // GL's zero-to-one perspective: 90°, near 1, far 10, looking down -z.
  const glm::mat4 clip = glm::perspectiveRH_ZO(glm::radians(90.0f), 1.0f, 1.0f, 10.0f);
  CHECK(!clipVolumeMisses(clip, box({-1, -1, -5}, {1, 1, -4})));             // in front, inside
  CHECK(clipVolumeMisses(clip, box({-1, -1, 1}, {1, 1, 2})));                // behind the eye
  CHECK(clipVolumeMisses(clip, box({-1, -1, -0.9f}, {1, 1, -0.5f})));        // nearer than near
  CHECK(clipVolumeMisses(clip, box({-1, -1, -30}, {1, 1, -20})));            // beyond far
  CHECK(clipVolumeMisses(clip, box({6, -1, -5}, {7, 1, -4})));               // right of x = w
  CHECK(clipVolumeMisses(clip, box({-7, -1, -5}, {-6, 1, -4})));             // left
  CHECK(clipVolumeMisses(clip, box({-1, 6, -5}, {1, 7, -4})));               // above
  CHECK(!clipVolumeMisses(clip, box({-100, -1, -5}, {100, 1, -4})));         // across the whole width
  CHECK(!clipVolumeMisses(clip, box({-1, -1, -50}, {1, 1, 50})));            // through eye, near and far
  // Past x = w and y = w at its near end (z = -1.5), inside at its far end (z = -6): not past one plane everywhere.
  CHECK(!clipVolumeMisses(clip, box({4, 4, -6}, {5, 5, -1.5f})));
  CHECK(clipVolumeMisses(clip, box({4, 4, -3}, {5, 5, -1.5f})));  // the same box cut off before it enters
  CHECK(clipVolumeMisses(clip, Bounds{}));  // empty: nothing to draw
}

TEST_CASE("Clip volume: no point of a box said to miss is inside, over random boxes and views") {
  std::mt19937 random(174);
  std::uniform_real_distribution<float> coordinate(-6.0f, 6.0f), extent(0.01f, 3.0f), unit(0.0f, 1.0f);
  const glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(70.0f), 1.3f, 0.5f, 12.0f);
  int missed = 0, kept = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const glm::mat4 view = glm::lookAtRH(glm::vec3(coordinate(random), coordinate(random), coordinate(random)), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const glm::vec3 lo{coordinate(random), coordinate(random), coordinate(random)};
    const Bounds b = box(lo, lo + glm::vec3(extent(random), extent(random), extent(random)));
    const glm::mat4 m = projection * view;
    if (!clipVolumeMisses(m, b)) {
      ++kept;
      continue;
    }
    ++missed;
    for (int k = 0; k < 64; ++k) {
      const glm::vec3 p = b.min + (b.max - b.min) * glm::vec3(unit(random), unit(random), unit(random));
      REQUIRE(!insideClip(m * glm::vec4(p, 1.0f)));
    }
  }
  // Both answers occur, so the property was tried.
  CHECK(missed > 500);
  CHECK(kept > 500);
}

}  // namespace
}  // namespace facet
