// Procedural textures (renderer/PIPELINE.md, "Textures"): the checker's
// parity and the value noise's lattice, range and continuity.
#include <algorithm>
#include <cmath>

#include <doctest/doctest.h>

#include "shading/procedural.h"

using namespace facet;

TEST_CASE("the checker is 1 on cells whose floor sum is even and 0.05 on odd ones, in model units times the scale") {
  CHECK(proceduralGrey(Procedural::Checker, {0.5f, 0.5f, 0.5f}, 1.0f) == 1.0f);
  CHECK(proceduralGrey(Procedural::Checker, {1.5f, 0.5f, 0.5f}, 1.0f) == 0.05f);
  CHECK(proceduralGrey(Procedural::Checker, {1.5f, 1.5f, 0.5f}, 1.0f) == 1.0f);
  CHECK(proceduralGrey(Procedural::Checker, {-0.5f, 0.5f, 0.5f}, 1.0f) == 0.05f);  // floor(-0.5) = -1: odd
  CHECK(proceduralGrey(Procedural::Checker, {-0.5f, -0.5f, 0.5f}, 1.0f) == 1.0f);
  CHECK(proceduralGrey(Procedural::Checker, {0.3f, 0.1f, 0.1f}, 4.0f) == 0.05f);  // 1.2: the second cell
  CHECK(proceduralGrey(Procedural::Checker, {1e30f, 0.5f, 0.5f}, 1.0f) == 1.0f);  // clamped to 2^24: even
}

TEST_CASE("value noise takes its lattice values at integer points, stays from 0 up to 1 and varies continuously") {
  for (int x = -3; x <= 3; ++x) CHECK(valueNoise({static_cast<float>(x), 2.0f, -1.0f}) == latticeValue(x, 2, -1));
  // The hash spreads neighbouring corners apart: 64 corners take many values.
  int distinct = 0;
  float previous = -1.0f;
  for (int x = 0; x < 64; ++x) {
    const float v = latticeValue(x, 0, 0);
    CHECK(v >= 0.0f);
    CHECK(v < 1.0f);
    distinct += std::fabs(v - previous) > 1e-3f;
    previous = v;
  }
  CHECK(distinct > 60);
  float lowest = 1.0f, highest = 0.0f, largestStep = 0.0f;
  previous = proceduralGrey(Procedural::Noise, {0.0f, 0.37f, 0.61f}, 1.0f);
  for (int i = 1; i <= 4000; ++i) {
    const float g = proceduralGrey(Procedural::Noise, {static_cast<float>(i) * 0.001f, 0.37f, 0.61f}, 1.0f);
    lowest = std::min(lowest, g), highest = std::max(highest, g);
    largestStep = std::max(largestStep, std::fabs(g - previous));
    previous = g;
  }
  CHECK(lowest >= 0.0f);
  CHECK(highest < 1.0f);
  CHECK(highest - lowest > 0.2f);     // it is a pattern, not a constant
  CHECK(largestStep < 0.02f);         // a thousandth of a cell moves it little: no jumps at cell faces
}
