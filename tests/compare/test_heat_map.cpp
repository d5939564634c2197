// The heat map: black where equal, brighter for larger differences, and a
// visible step up where pixels start to fail.
#include <cstdlib>

#include <doctest/doctest.h>

#include "compare/color_ramp.h"
#include "compare/heat_map.h"
#include "test_images.h"

using namespace facet;
using namespace facet::test;

namespace {

// Rec. 709 luma of the sRGB values: enough to tell brighter from darker.
double luma(Rgba8 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

bool near(Rgba8 c, int r, int g, int b) { return std::abs(c.r - r) <= 2 && std::abs(c.g - g) <= 2 && std::abs(c.b - b) <= 2; }

}  // namespace

TEST_CASE("the ramp is matplotlib's inferno: black, crimson in the middle, pale yellow at the end") {
  CHECK(near(inferno(0.0), 0, 0, 4));
  CHECK(near(inferno(0.5), 188, 55, 84));
  CHECK(near(inferno(1.0), 252, 255, 164));
  CHECK(inferno(-1.0) == inferno(0.0));
  CHECK(inferno(2.0) == inferno(1.0));
}

TEST_CASE("heat-map colours grow brighter with the difference, with a step where pixels fail") {
  for (const double fail : {0.0, 1.0 / 255.0, 10.0 / 255.0, 1.0}) {
    DiffThresholds t;
    t.failThreshold = fail;
    CAPTURE(fail);
    CHECK(heatMapColor(0, t) == Rgba8{0, 0, 0, 255});
    for (int d = 1; d < 256; ++d) {
      CAPTURE(d);
      CHECK(heatMapColor(d, t).a == 255);
      // Inferno's blue falls while its red and green rise; rounded to 8 bits,
      // one step can lose a couple of blue levels (0.07 of luma each) before
      // red or green gains one. Anything more would be a real reversal.
      CHECK(luma(heatMapColor(d, t)) > luma(heatMapColor(d - 1, t)) - 0.25);
    }
  }
  DiffThresholds oneStep;  // one step passes, two fail
  oneStep.failThreshold = 1.0 / 255.0;
  const Rgba8 passing = heatMapColor(1, oneStep), failing = heatMapColor(2, oneStep);
  CHECK(luma(passing) > 30.0);   // visible on black
  CHECK(luma(passing) < 100.0);  // but quiet
  CHECK(luma(failing) > luma(passing) + 20.0);  // a visible step up at the threshold
  CHECK(failing.r > 200);        // failing pixels are orange to yellow
  CHECK(heatMapColor(255, oneStep) == inferno(1.0));
  CHECK(heatMapColor(1, DiffThresholds{}) == failing);  // idiff's defaults: one step fails
}

TEST_CASE("a heat map is black where the images agree and lights up where they differ") {
  const Image expected = objectImage(10, 10, 2, 5), actual = objectImage(10, 10, 2, 6);
  const DiffThresholds defaults;
  const Image map = heatMap(expected, actual, defaults);
  REQUIRE(map.width() == 10);
  REQUIRE(map.height() == 10);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) CHECK(map.at(x, y) == (x == 5 ? heatMapColor(255, defaults) : Rgba8{0, 0, 0, 255}));
}
