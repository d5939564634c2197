// compareImages on changes whose figures can be worked out by hand.
#include <cmath>

#include <doctest/doctest.h>

#include "common/error.h"
#include "compare/diff_format.h"
#include "compare/image_diff.h"
#include "test_images.h"

using namespace facet;
using namespace facet::test;

namespace {

bool sameBox(const PixelBox& box, int minX, int minY, int maxX, int maxY) {
  return box.minX == minX && box.minY == minY && box.maxX == maxX && box.maxY == maxY;
}

}  // namespace

TEST_CASE("two identical images pass, with every figure zero and PSNR infinite") {
  const Image image = objectImage(10, 10, 2, 6);
  const DiffResult r = compareImages(image, image, {});
  CHECK(r.status == DiffStatus::Pass);
  for (const ChannelDiff& c : r.channels) {
    CHECK(c.max == 0);
    CHECK(c.mean == 0.0);
  }
  CHECK(r.maxDifference == 0);
  CHECK(r.meanError == 0.0);
  CHECK(r.rmse == 0.0);
  CHECK(std::isinf(r.psnr));
  CHECK(r.differingPixels == 0);
  CHECK(r.failingPixels == 0);
  CHECK(r.warningPixels == 0);
  CHECK(r.differing.empty());
  CHECK(r.failing.empty());
  CHECK(r.worst.x == -1);
}

TEST_CASE("one pixel off by 10 in red on a 10x10 image: the figures worked out by hand") {
  const Image expected(10, 10, kSlate);
  const Image actual = withPixel(expected, 3, 5, {20, 20, 40, 255});
  const DiffResult r = compareImages(expected, actual, {});

  CHECK(r.channels[0].max == 10);
  CHECK(r.channels[0].mean == doctest::Approx(0.1));  // 10 / 100 pixels
  for (std::size_t c = 1; c < 4; ++c) {
    CHECK(r.channels[c].max == 0);
    CHECK(r.channels[c].mean == 0.0);
  }
  CHECK(r.maxDifference == 10);
  // Over R, G, B, A (facet's images store all four), as idiff: mean error
  // 10 / (4 * 100) = 0.025; RMSE sqrt(10^2 / (4 * 100)) = 0.5; PSNR
  // 20 log10(255 / 0.5) = 54.1514 dB.
  CHECK(r.meanError == doctest::Approx(0.025));
  CHECK(r.rmse == doctest::Approx(0.5));
  CHECK(r.psnr == doctest::Approx(54.1514).epsilon(1e-5));

  CHECK(r.differingPixels == 1);
  CHECK(r.failingPixels == 1);
  CHECK(r.failingPercent == doctest::Approx(1.0));
  CHECK(r.warningPixels == 1);
  CHECK(sameBox(r.differing, 3, 5, 3, 5));
  CHECK(sameBox(r.failing, 3, 5, 3, 5));
  CHECK(r.worst.x == 3);
  CHECK(r.worst.y == 5);
  CHECK(r.worst.channel == 0);
  CHECK(r.worst.difference == 10);
  CHECK(r.worst.expected == kSlate);
  CHECK(r.worst.actual == Rgba8{20, 20, 40, 255});
  CHECK(r.status == DiffStatus::Fail);

  // Reports count rows from the top: stored row 5 of 10 is row 4 from the top.
  CHECK(formatBox(r.differing, r.height) == "x 3..3, y 4..4");
  CHECK(formatPosition(r.worst.x, r.worst.y, r.height) == "(3, 4)");
}

TEST_CASE("a colour shift of 2/255 over the whole image fails, and tolerating two steps turns it into a warning, then a pass") {
  // R, G, B two levels off, A equal: RMSE sqrt(3 * 2^2 / 4) = sqrt(3).
  const Image dark(8, 6, kSlate);
  const Image darkShifted = shifted(dark, 2);
  const DiffResult r = compareImages(dark, darkShifted, {});
  for (std::size_t c = 0; c < 3; ++c) {
    CHECK(r.channels[c].max == 2);
    CHECK(r.channels[c].mean == doctest::Approx(2.0));
  }
  CHECK(r.channels[3].max == 0);
  CHECK(r.meanError == doctest::Approx(1.5));
  CHECK(r.rmse == doctest::Approx(std::sqrt(3.0)));
  CHECK(r.psnr == doctest::Approx(43.3596).epsilon(1e-5));  // 20 log10(255 / sqrt(3))
  CHECK(r.failingPixels == 48);
  CHECK(r.failingPercent == doctest::Approx(100.0));
  CHECK(sameBox(r.differing, 0, 0, 7, 5));
  CHECK(sameBox(r.failing, 0, 0, 7, 5));
  CHECK(r.status == DiffStatus::Fail);

  DiffThresholds twoSteps;
  twoSteps.failThreshold = 2.0 / 255.0;
  CHECK(compareImages(dark, darkShifted, twoSteps).status == DiffStatus::Warn);
  twoSteps.warnThreshold = 2.0 / 255.0;
  CHECK(compareImages(dark, darkShifted, twoSteps).status == DiffStatus::Pass);
}

TEST_CASE("an object edge moved by one pixel fails on exactly that column") {
  const Image expected = objectImage(10, 10, 2, 5);
  const Image actual = objectImage(10, 10, 2, 6);  // right edge one pixel further right
  const DiffResult r = compareImages(expected, actual, {});
  CHECK(r.differingPixels == 10);
  CHECK(r.failingPixels == 10);
  CHECK(r.failingPercent == doctest::Approx(10.0));
  CHECK(sameBox(r.differing, 5, 0, 5, 9));
  CHECK(sameBox(r.failing, 5, 0, 5, 9));
  CHECK(r.maxDifference == 255);
  CHECK(r.channels[0].mean == doctest::Approx(25.5));  // 10 x 255 / 100
  CHECK(r.channels[3].max == 0);
  // RMSE: sqrt(10 pixels x 3 x 255^2 / 400) = 255 sqrt(3 / 40); PSNR: 20 log10(sqrt(40 / 3)) = 11.249 dB.
  CHECK(r.rmse == doctest::Approx(255.0 * std::sqrt(3.0 / 40.0)));
  CHECK(r.psnr == doctest::Approx(11.2494).epsilon(1e-5));
  CHECK(r.worst.x == 5);
  CHECK(r.worst.y == 9);  // the column's top pixel: idiff reads rows from the top
  CHECK(r.worst.expected == kBlack);
  CHECK(r.worst.actual == kWhite);
  CHECK(r.status == DiffStatus::Fail);
}

TEST_CASE("alpha counts toward failing pixels, and toward the mean error and RMSE as one of four channels") {
  const Image expected(4, 4, kSlate);
  const Image actual = withPixel(expected, 0, 0, {10, 20, 40, 0});
  const DiffResult r = compareImages(expected, actual, {});
  CHECK(r.channels[3].max == 255);
  CHECK(r.failingPixels == 1);
  CHECK(r.meanError == doctest::Approx(255.0 / 64.0));  // 16 pixels x 4 channels
  CHECK(r.rmse == doctest::Approx(255.0 / 8.0));        // sqrt(255^2 / 64)
  CHECK(r.psnr == doctest::Approx(18.0618).epsilon(1e-5));  // 20 log10(8)
  CHECK(r.status == DiffStatus::Fail);
}

TEST_CASE("the mean error and RMSE average over the channels the files store, as idiff's") {
  const Image expected(10, 10, kSlate);
  const Image redOff = withPixel(expected, 3, 5, {20, 20, 40, 255});  // R 10 levels off
  CHECK(compareImages(expected, redOff, {}, {true, true}).rmse == doctest::Approx(0.5));  // sqrt(100 / 400)
  const DiffResult rgb = compareImages(expected, redOff, {}, {true, false});
  CHECK(rgb.rmse == doctest::Approx(std::sqrt(100.0 / 300.0)));
  CHECK(rgb.meanError == doctest::Approx(10.0 / 300.0));
  CHECK(rgb.storedChannels == StoredChannels{true, false});
  // A grey file's one channel fills R, G and B: it counts once.
  const Image grey(10, 10, {50, 50, 50, 255});
  const Image greyOff = withPixel(grey, 0, 0, {60, 60, 60, 255});
  const DiffResult y = compareImages(grey, greyOff, {}, {false, false});
  CHECK(y.rmse == doctest::Approx(1.0));  // sqrt(100 / 100)
  CHECK(y.meanError == doctest::Approx(0.1));
  CHECK(compareImages(grey, greyOff, {}, {false, true}).rmse == doctest::Approx(std::sqrt(0.5)));  // Y and A: sqrt(100 / 200)
}

TEST_CASE("the max error is the first largest channel difference in reading order, as idiff's") {
  Image actual(6, 4, kSlate);
  actual.at(1, 1) = {13, 20, 40, 255};  // 3
  actual.at(4, 2) = {10, 60, 40, 255};  // 40
  actual.at(5, 3) = {10, 20, 45, 255};  // 5
  DiffResult r = compareImages(Image(6, 4, kSlate), actual, {});
  CHECK(r.worst.x == 4);
  CHECK(r.worst.y == 2);
  CHECK(r.worst.channel == 1);
  CHECK(r.worst.difference == 40);
  CHECK(sameBox(r.differing, 1, 1, 5, 3));

  // Ties: the higher row (y = 3 is the top row of 4), then the left pixel, then R before G, B, A.
  actual.at(0, 1) = {10, 60, 40, 255};  // 40, a lower row
  actual.at(5, 3) = {10, 20, 80, 255};  // 40, the top row, right
  actual.at(2, 3) = {10, 20, 40, 215};  // 40, the top row, left, in A
  r = compareImages(Image(6, 4, kSlate), actual, {});
  CHECK(r.worst.x == 2);
  CHECK(r.worst.y == 3);
  CHECK(r.worst.channel == 3);
  actual.at(2, 3) = {50, 20, 40, 215};  // R ties A in the same pixel
  r = compareImages(Image(6, 4, kSlate), actual, {});
  CHECK(r.worst.channel == 0);
  CHECK(r.worst.x == 2);
}

TEST_CASE("images of different sizes are refused, naming both sizes") {
  CHECK_THROWS_WITH_AS(compareImages(Image(10, 10), Image(12, 10), {}), doctest::Contains("expected 10x10, actual 12x10"), Error);
}
