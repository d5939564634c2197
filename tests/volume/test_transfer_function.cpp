// Transfer functions: control points parsed from volume.transfer, the
// presets over a data range, evaluation, and every error line.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <utility>

#include <doctest/doctest.h>

#include "common/error.h"
#include "scene/transfer_function.h"

using namespace facet;

namespace {

std::string errorOf(const std::function<void()>& parse) {
  try {
    parse();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// The error line of parsing `text`: it names volume.transfer and says `problem`.
void checkError(const std::string& text, const std::string& problem) {
  const std::string message = errorOf([&] { parseTransferFunction(text, 0.0f, 255.0f); });
  CAPTURE(text);
  CAPTURE(message);
  CHECK(message.rfind("volume.transfer: ", 0) == 0);
  CHECK(message.find(problem) != std::string::npos);
  CHECK(message.find('\n') == std::string::npos);
}

void checkRgba(glm::vec4 actual, glm::vec4 expected) {
  for (int i = 0; i < 4; ++i) {
    CAPTURE(i);
    CHECK(actual[i] == doctest::Approx(expected[i]));
  }
}

}  // namespace

TEST_CASE("transfer function: control points parsed in order, with their colours and opacities") {
  const TransferFunction f = parseTransferFunction("0 0 0 0 0, 80 1 0.8 0.6 0.05, 255 1 1 1 0.9", 0.0f, 255.0f);
  REQUIRE(f.points.size() == 3);
  CHECK(f.points[0].value == 0.0f);
  CHECK(f.points[1].value == 80.0f);
  CHECK(f.points[1].color == glm::vec3(1.0f, 0.8f, 0.6f));
  CHECK(f.points[1].opacity == 0.05f);
  CHECK(f.points[2].value == 255.0f);
  CHECK(f.points[2].opacity == 0.9f);
  // Spacing is free: tabs, several spaces, a leading +, exponents, negative values.
  const TransferFunction g = parseTransferFunction("  -1e3\t0 0 0 0 ,   +2.5e1 0.5 .5 1 1  ", -1000.0f, 25.0f);
  REQUIRE(g.points.size() == 2);
  CHECK(g.points[0].value == -1000.0f);
  CHECK(g.points[1].value == 25.0f);
  CHECK(g.points[1].color == glm::vec3(0.5f, 0.5f, 1.0f));
}

TEST_CASE("transfer function: piecewise linear between points, clamped at the ends") {
  const TransferFunction f = parseTransferFunction("10 0 0 0 0, 20 1 0.5 0 0.2, 60 0 1 1 1", 0.0f, 100.0f);
  checkRgba(f(10.0f), {0.0f, 0.0f, 0.0f, 0.0f});
  checkRgba(f(15.0f), {0.5f, 0.25f, 0.0f, 0.1f});
  checkRgba(f(20.0f), {1.0f, 0.5f, 0.0f, 0.2f});
  checkRgba(f(30.0f), {0.75f, 0.625f, 0.25f, 0.4f});
  checkRgba(f(60.0f), {0.0f, 1.0f, 1.0f, 1.0f});
  // Below the first point: the first point's, above the last: the last's.
  checkRgba(f(-1000.0f), {0.0f, 0.0f, 0.0f, 0.0f});
  checkRgba(f(9.99f), {0.0f, 0.0f, 0.0f, 0.0f});
  checkRgba(f(60.01f), {0.0f, 1.0f, 1.0f, 1.0f});
  checkRgba(f(std::numeric_limits<float>::infinity()), {0.0f, 1.0f, 1.0f, 1.0f});
  checkRgba(f(std::numeric_limits<float>::quiet_NaN()), {0.0f, 0.0f, 0.0f, 0.0f});
  // Each component is a + t·(b − a).
  const float t = (17.0f - 10.0f) / (20.0f - 10.0f);
  CHECK(f(17.0f).w == 0.0f + t * (0.2f - 0.0f));
  // One point: that point everywhere.
  const TransferFunction one = parseTransferFunction("5 0.2 0.4 0.6 0.8", 0.0f, 1.0f);
  checkRgba(one(-1.0f), {0.2f, 0.4f, 0.6f, 0.8f});
  checkRgba(one(5.0f), {0.2f, 0.4f, 0.6f, 0.8f});
  checkRgba(one(1e6f), {0.2f, 0.4f, 0.6f, 0.8f});
}

TEST_CASE("transfer function presets: each spans the data range with increasing points") {
  const auto names = transferPresetNames();
  REQUIRE(names.size() >= 3);
  for (const std::string_view name : {"grey", "mri", "bone", "rainbow", "iso-surface"})
    CHECK(std::find(names.begin(), names.end(), name) != names.end());
  for (const std::string_view name : names) {
    CAPTURE(name);
    for (const auto& range : {std::pair{-610.0f, 30393.0f}, std::pair{0.0f, 1.0f}, std::pair{7.0f, 7.0f}}) {
      const float lo = range.first, hi = range.second;  // named, not bound: CAPTURE's lambda takes them
      CAPTURE(lo);
      const TransferFunction f = parseTransferFunction(name, lo, hi);
      REQUIRE(f.points.size() >= 2);
      CHECK(f.points.front().value == lo);
      CHECK(f.points.back().value == (hi > lo ? hi : lo + 1.0f));  // an empty range becomes a unit one
      for (std::size_t i = 0; i < f.points.size(); ++i) {
        const TransferPoint& p = f.points[i];
        if (i > 0) CHECK(p.value > f.points[i - 1].value);
        for (int c = 0; c < 3; ++c) CHECK((p.color[c] >= 0.0f && p.color[c] <= 1.0f));
        CHECK((p.opacity >= 0.0f && p.opacity <= 1.0f));
      }
      CHECK(f(lo).w == 0.0f);  // the lowest values are transparent in every preset
    }
  }
  // Grey: black and transparent to white, a linear ramp.
  const TransferFunction grey = parseTransferFunction("  grey ", 0.0f, 200.0f);
  checkRgba(grey(100.0f), {0.5f, 0.5f, 0.5f, 0.4f});
  checkRgba(grey(200.0f), {1.0f, 1.0f, 1.0f, 0.8f});
  // Bone: transparent up to 40 % of the range, then ivory and more opaque.
  const TransferFunction bone = parseTransferFunction("bone", 0.0f, 1000.0f);
  CHECK(bone(399.0f).w == 0.0f);
  CHECK(bone(700.0f).w > 0.4f);
  CHECK(bone(1000.0f).x > 0.9f);
  // MRI: the background transparent, bright tissue more opaque than soft tissue.
  const TransferFunction mri = parseTransferFunction("mri", -610.0f, 30393.0f);
  CHECK(mri(0.0f).w == 0.0f);
  CHECK(mri(10000.0f).w > 0.0f);
  CHECK(mri(28000.0f).w > mri(10000.0f).w);
  // Iso-surface: opaque at the middle of the range only.
  const TransferFunction iso = parseTransferFunction("iso-surface", 0.0f, 1.0f);
  CHECK(iso(0.5f).w == doctest::Approx(0.9f));
  CHECK(iso(0.3f).w == 0.0f);
  CHECK(iso(0.8f).w == 0.0f);
  // A range floats cannot split still gives increasing points.
  const TransferFunction tight = parseTransferFunction("rainbow", 1e30f, 1e30f);
  for (std::size_t i = 1; i < tight.points.size(); ++i) CHECK(tight.points[i].value > tight.points[i - 1].value);
}

TEST_CASE("transfer function errors: one line naming volume.transfer and the point at fault") {
  SUBCASE("empty text") {
    checkError("", "empty (give a preset, one of grey, mri, bone, rainbow, iso-surface");
    checkError(" \t ", "empty");
  }
  SUBCASE("unknown preset, listing the presets") { checkError("jet", "unknown preset 'jet' (presets: grey, mri, bone, rainbow, iso-surface)"); }
  SUBCASE("values not increasing") {
    checkError("0 0 0 0 0, 80 1 0.8 0.6 0.05, 10 1 1 1 0.9", "point 3 (value 10) is not above point 2 (value 80)");
    checkError("5 0 0 0 0, 5 1 1 1 1", "point 2 (value 5) is not above point 1 (value 5)");
  }
  SUBCASE("a number missing or one too many") {
    checkError("0 0 0 0 0, 80 1 0.8 0.6", "point 2 has 4 numbers, expected 5 (value r g b a)");
    checkError("0 0 0 0", "point 1 has 4 numbers, expected 5");
    checkError("0 0 0 0 0 1 1 1 1 1", "point 1 has 10 numbers, expected 5 (value r g b a; points are separated by commas)");
    checkError("0 0 0 0 0,", "point 2 is empty");
    checkError("0 0 0 0 0,, 9 1 1 1 1", "point 2 is empty");
  }
  SUBCASE("something that is not a number") {
    checkError("0 0 0 0 0, 80 1 x 0.6 0.05", "point 2: 'x' is not a number");
    checkError("0 0 0 0 0, 80 1 0.8.1 0.6 0.05", "point 2: '0.8.1' is not a number");
    checkError("0 0 0 0 0; 80 1 0 0.6 0.05", "point 1: '0;' is not a number");
  }
  SUBCASE("numbers that are not finite") {
    checkError("inf 0 0 0 0", "point 1: 'inf' is not a finite number");
    checkError("0 0 0 0 0, 1 nan 0 0 0", "point 2: 'nan' is not a finite number");
    checkError("1e99 0 0 0 0", "point 1: '1e99' is not a finite number");
  }
  SUBCASE("a colour or opacity outside [0, 1]") {
    checkError("0 1.5 0 0 0", "point 1: red 1.5 is outside [0, 1]");
    checkError("0 0 0 0 0, 9 0 -0.25 0 0", "point 2: green -0.25 is outside [0, 1]");
    checkError("0 0 0 2 0", "point 1: blue 2 is outside [0, 1]");
    checkError("0 0 0 0 0, 1 0 0 0 0, 2 0 0 0 1.01", "point 3: opacity 1.01 is outside [0, 1]");
  }
}
