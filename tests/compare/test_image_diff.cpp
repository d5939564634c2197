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
  // RMSE over R, G, B: sqrt(10^2 / (3 * 100)) = sqrt(1/3) = 0.57735.
  CHECK(r.rmse == doctest::Approx(0.5773503).epsilon(1e-6));
  // PSNR: 20 log10(255 / 0.57735) = 20 log10(441.673) = 52.902 dB.
  CHECK(r.psnr == doctest::Approx(52.902).epsilon(1e-4));

  CHECK(r.differingPixels == 1);
  CHECK(r.failingPixels == 1);
  CHECK(r.failingPercent == doctest::Approx(1.0));
  CHECK(r.warningPixels == 1);
  CHECK(sameBox(r.differing, 3, 5, 3, 5));
  CHECK(sameBox(r.failing, 3, 5, 3, 5));
  CHECK(r.worst.x == 3);
  CHECK(r.worst.y == 5);
  CHECK(r.worst.difference == 10);
  CHECK(r.worst.expected == kSlate);
  CHECK(r.worst.actual == Rgba8{20, 20, 40, 255});
  CHECK(r.status == DiffStatus::Fail);

  // Reports count rows from the top: stored row 5 of 10 is row 4 from the top.
  CHECK(formatBox(r.differing, r.height) == "x 3..3, y 4..4");
  CHECK(formatPosition(r.worst.x, r.worst.y, r.height) == "(3, 4)");
}

TEST_CASE("a colour shift of 2/255 over the whole image fails, and tolerating two steps turns it into a warning, then a pass") {
  const Image dark(8, 6, kSlate);
  const Image darkShifted = shifted(dark, 2);
  const DiffResult r = compareImages(dark, darkShifted, {});
  for (std::size_t c = 0; c < 3; ++c) {
    CHECK(r.channels[c].max == 2);
    CHECK(r.channels[c].mean == doctest::Approx(2.0));
  }
  CHECK(r.channels[3].max == 0);
  CHECK(r.rmse == doctest::Approx(2.0));
  CHECK(r.psnr == doctest::Approx(42.1102).epsilon(1e-5));  // 20 log10(255 / 2)
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
  // RMSE: sqrt(10 pixels x 3 x 255^2 / 300) = 255 / sqrt(10); PSNR: 20 log10(sqrt(10)) = 10 dB.
  CHECK(r.rmse == doctest::Approx(255.0 / std::sqrt(10.0)));
  CHECK(r.psnr == doctest::Approx(10.0));
  CHECK(r.worst.x == 5);
  CHECK(r.worst.expected == kBlack);
  CHECK(r.worst.actual == kWhite);
  CHECK(r.status == DiffStatus::Fail);
}

TEST_CASE("alpha counts toward failing pixels but not toward RMSE") {
  const Image expected(4, 4, kSlate);
  const Image actual = withPixel(expected, 0, 0, {10, 20, 40, 0});
  const DiffResult r = compareImages(expected, actual, {});
  CHECK(r.channels[3].max == 255);
  CHECK(r.failingPixels == 1);
  CHECK(r.rmse == 0.0);
  CHECK(std::isinf(r.psnr));
  CHECK(r.status == DiffStatus::Fail);
}

TEST_CASE("the worst pixel is the one with the largest channel difference") {
  Image actual(6, 4, kSlate);
  actual.at(1, 1) = {13, 20, 40, 255};  // 3
  actual.at(4, 2) = {10, 60, 40, 255};  // 40
  actual.at(5, 3) = {10, 20, 45, 255};  // 5
  const DiffResult r = compareImages(Image(6, 4, kSlate), actual, {});
  CHECK(r.worst.x == 4);
  CHECK(r.worst.y == 2);
  CHECK(r.worst.difference == 40);
  CHECK(sameBox(r.differing, 1, 1, 5, 3));
}

TEST_CASE("images of different sizes are refused, naming both sizes") {
  CHECK_THROWS_WITH_AS(compareImages(Image(10, 10), Image(12, 10), {}), doctest::Contains("expected 10x10, actual 12x10"), Error);
}
