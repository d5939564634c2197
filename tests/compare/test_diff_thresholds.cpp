// idiff's pass / warn / fail rule, and thresholds as fractions of full scale.
#include <cmath>

#include <doctest/doctest.h>

#include "common/error.h"
#include "compare/image_diff.h"
#include "test_images.h"

using namespace facet;
using namespace facet::test;

TEST_CASE("a fraction of full scale tolerates whole 8-bit steps") {
  CHECK(toleratedLevels(0.0) == 0);
  CHECK(toleratedLevels(1.0 / 255.0) == 1);
  CHECK(toleratedLevels(2.0 / 255.0) == 2);
  CHECK(toleratedLevels(0.004) == 1);   // idiff's "just above 1/255"
  CHECK(toleratedLevels(0.0039) == 0);  // just below one step
  CHECK(toleratedLevels(1.0) == 255);
  CHECK(toleratedLevels(kNoLimit) == 255);
}

TEST_CASE("thresholds out of range are named") {
  DiffThresholds t;
  t.failThreshold = -0.1;
  CHECK_THROWS_WITH_AS(checkThresholds(t), doctest::Contains("diff threshold fail"), Error);
  t = {};
  t.warnPercent = 101;
  CHECK_THROWS_WITH_AS(checkThresholds(t), doctest::Contains("diff threshold warnpercent"), Error);
  t = {};
  t.hardFail = std::nan("");
  CHECK_THROWS_WITH_AS(checkThresholds(t), doctest::Contains("diff threshold hardfail"), Error);
  CHECK_NOTHROW(checkThresholds(DiffThresholds{}));
}

TEST_CASE("by default, as in idiff, any difference fails, and --fail 1/255 lets one 8-bit step warn instead") {
  const Image expected(10, 10, kSlate);
  const Image oneStep = withPixel(expected, 0, 0, {11, 20, 40, 255}), twoSteps = withPixel(expected, 0, 0, {12, 20, 40, 255});
  CHECK(compareImages(expected, expected, {}).status == DiffStatus::Pass);
  CHECK(compareImages(expected, oneStep, {}).status == DiffStatus::Fail);
  DiffThresholds t;
  t.failThreshold = 1.0 / 255.0;
  CHECK(compareImages(expected, oneStep, t).status == DiffStatus::Warn);
  CHECK(compareImages(expected, twoSteps, t).status == DiffStatus::Fail);
}

TEST_CASE("allowFailures passes up to that many failing pixels, by any amount, and is off at 0") {
  // 10 failing pixels out of 100 (a column, 255 levels off).
  const Image expected = objectImage(10, 10, 2, 5), actual = objectImage(10, 10, 2, 6);
  DiffThresholds t;
  t.hardFail = 0.5;
  t.hardWarn = 0.5;
  t.allowFailures = 10;
  CHECK(compareImages(expected, actual, t).status == DiffStatus::Pass);  // warn thresholds and hard limits too
  t.allowFailures = 9;
  CHECK(compareImages(expected, actual, t).status == DiffStatus::Fail);
  // 0 lets nothing through: with no pixel over --fail, --warn still warns
  // (idiff 2.4 passes there; its help, and facet, say otherwise).
  t = {};
  t.failThreshold = 1.0;
  CHECK(compareImages(expected, actual, t).status == DiffStatus::Warn);
  t.allowFailures = -1;
  CHECK_THROWS_WITH_AS(checkThresholds(t), doctest::Contains("diff threshold allowfailures"), Error);
}

TEST_CASE("failpercent allows up to that share of failing pixels, and hardfail fails regardless") {
  // 10 failing pixels out of 100 (a column, 255 levels off).
  const Image expected = objectImage(10, 10, 2, 5), actual = objectImage(10, 10, 2, 6);
  DiffThresholds t;
  t.failPercent = 10.0;  // "more than 10%" fails, as in idiff: exactly 10% does not
  CHECK(compareImages(expected, actual, t).status == DiffStatus::Warn);
  t.failPercent = 9.9;
  CHECK(compareImages(expected, actual, t).status == DiffStatus::Fail);
  t.failPercent = 10.0;
  t.hardFail = 0.5;  // 128 levels; the column is 255 off
  CHECK(compareImages(expected, actual, t).status == DiffStatus::Fail);
  t.hardFail = 1.0;
  CHECK(compareImages(expected, actual, t).status == DiffStatus::Warn);
}

TEST_CASE("warn thresholds work the same way, one level down") {
  const Image expected(10, 10, kSlate);
  const Image actual = withPixel(expected, 4, 4, {15, 20, 40, 255});  // 5 levels, 1%
  DiffThresholds t;
  t.failThreshold = 10.0 / 255.0;
  CHECK(compareImages(expected, actual, t).status == DiffStatus::Warn);
  t.warnPercent = 1.0;
  CHECK(compareImages(expected, actual, t).status == DiffStatus::Pass);
  t.hardWarn = 4.0 / 255.0;
  CHECK(compareImages(expected, actual, t).status == DiffStatus::Warn);
  t.hardWarn = 5.0 / 255.0;
  CHECK(compareImages(expected, actual, t).status == DiffStatus::Pass);
}
