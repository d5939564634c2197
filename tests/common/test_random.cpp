// common/random.h: SplitMix64's published sequence, and its two conversions
// to [0, 1) as the exact fractions anti-aliasing's jitter, the ray tracer
// (top 24 bits) and the particles (top 53 bits) take them to be.
#include <cstdint>
#include <initializer_list>

#include <doctest/doctest.h>

#include "common/random.h"

using namespace facet;

TEST_CASE("SplitMix64: the published sequence, from Rosetta Code's seed 1234567 and the reference code's seed 0") {
  SplitMix64 rosetta(1234567);
  for (const std::uint64_t expected : {6457827717110365317ull, 3203168211198807973ull, 9817491932198370423ull, 4593380528125082431ull,
                                       16408922859458223821ull})
    CHECK(rosetta.next() == expected);
  SplitMix64 zero(0);
  CHECK(zero.next() == 0xE220A8397B1DCDAFull);
  CHECK(zero.next() == 0x6E789E6AA1B965F4ull);
  CHECK(zero.next() == 0x06C45D188009454Full);
}

TEST_CASE("SplitMix64: unitFloat is k/2^24 of the top 24 bits, unitDouble k/2^53 of the top 53, both below 1") {
  SplitMix64 bits(42), floats(42), doubles(42);
  for (int i = 0; i < 100000; ++i) {
    const std::uint64_t b = bits.next();
    const float f = floats.unitFloat();
    const double d = doubles.unitDouble();
    REQUIRE(static_cast<double>(f) == static_cast<double>(b >> 40) / 16777216.0);
    REQUIRE(d == static_cast<double>(b >> 11) / 9007199254740992.0);
    REQUIRE(f < 1.0f);
    REQUIRE(d < 1.0);
  }
  // Rosetta Code's check of the 53-bit conversion: 100000 numbers from seed 987654321 in five bins.
  SplitMix64 rosetta(987654321);
  int bins[5] = {};
  for (int i = 0; i < 100000; ++i) ++bins[static_cast<int>(rosetta.unitDouble() * 5.0)];
  CHECK(bins[0] == 20027);
  CHECK(bins[1] == 19892);
  CHECK(bins[2] == 20073);
  CHECK(bins[3] == 19978);
  CHECK(bins[4] == 20030);
}
