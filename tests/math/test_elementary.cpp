// facet's own tan, atan, atan2 and acos: correctly rounded in float, which
// is what makes them the same on every platform whose C library is (glibc
// 2.41 and later) and not only on those.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>

#include <doctest/doctest.h>

#include "math/elementary.h"

using namespace facet;

namespace {

// xorshift64: the same arguments on every run.
struct Arguments {
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  double next() {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  }
  float in(double lo, double hi) { return static_cast<float>(lo + (hi - lo) * next()); }
};

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The correctly rounded float of a long double value: long double's 64-bit
// significand leaves a float rounding undecided only within 2^-40 of a
// midpoint, which none of these arguments comes near.
float rounded(long double v) { return static_cast<float>(v); }

constexpr int kDraws = 200000;

}  // namespace

TEST_CASE("elementary: tan, atan, atan2 and acos are correctly rounded in float") {
  Arguments a;
  int wrong = 0;
  for (int i = 0; i < kDraws; ++i) {
    const float x = a.in(-1.58, 1.58), y = a.in(-30.0, 30.0), c = a.in(-1.0, 1.0), u = a.in(-4.0, 4.0), v = a.in(-4.0, 4.0);
    wrong += !sameBits(elementary::tan(x), rounded(tanl(x)));
    wrong += !sameBits(elementary::atan(y), rounded(atanl(y)));
    wrong += !sameBits(elementary::acos(c), rounded(acosl(c)));
    wrong += !sameBits(elementary::atan2(u, v), rounded(atan2l(u, v)));
  }
  CHECK(wrong == 0);
  // The camera's arguments: half angles of whole and half degrees, and the default scene's.
  for (int tenths = 5; tenths < 900; tenths += 5) {
    const float theta = static_cast<float>(tenths) * 0.1f * (std::numbers::pi_v<float> / 180.0f);
    CHECK(sameBits(elementary::tan(theta), rounded(tanl(theta))));
    CHECK(sameBits(elementary::atan(elementary::tan(theta)), rounded(atanl(elementary::tan(theta)))));
  }
}

TEST_CASE("elementary: tan, atan, atan2 and acos at the edges of their domains") {
  const float inf = INFINITY;
  CHECK(std::isnan(elementary::tan(inf)));
  CHECK(std::isnan(elementary::tan(NAN)));
  CHECK(sameBits(elementary::tan(-0.0f), -0.0f));
  CHECK(sameBits(elementary::atan(-0.0f), -0.0f));
  CHECK(elementary::atan(inf) == rounded(std::numbers::pi_v<long double> / 2));
  CHECK(elementary::atan(-inf) == -rounded(std::numbers::pi_v<long double> / 2));
  CHECK(elementary::acos(1.0f) == 0.0f);
  CHECK(elementary::acos(-1.0f) == rounded(std::numbers::pi_v<long double>));
  CHECK(std::isnan(elementary::acos(1.0000001f)));
  CHECK(std::isnan(elementary::acos(NAN)));
  CHECK(sameBits(elementary::atan2(0.0f, 1.0f), 0.0f));
  CHECK(sameBits(elementary::atan2(-0.0f, 1.0f), -0.0f));
  CHECK(elementary::atan2(0.0f, -1.0f) == rounded(std::numbers::pi_v<long double>));
  CHECK(elementary::atan2(-0.0f, -1.0f) == -rounded(std::numbers::pi_v<long double>));
  CHECK(elementary::atan2(1.0f, 0.0f) == rounded(std::numbers::pi_v<long double> / 2));
  CHECK(elementary::atan2(inf, -inf) == rounded(3 * std::numbers::pi_v<long double> / 4));
  CHECK(std::isnan(elementary::atan2(NAN, 1.0f)));
  // Large arguments are reduced without a libm call: the same bits everywhere, finite.
  CHECK(std::isfinite(elementary::tan(1e30f)));
}
