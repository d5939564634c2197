#pragma once
// double to float the way IEEE 754 rounds, written out: C++ leaves a double
// beyond float's range undefined when converted, IEEE gives ±infinity. And
// the two directed roundings a bounding box needs, so a box built from
// double values still contains them.
#include <cmath>
#include <limits>

namespace facet::ray {

// To nearest; beyond float's range, ±infinity; NaN stays NaN.
inline float toFloat(double x) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (x > kMax) return x < 0x1.ffffff0p127 ? std::numeric_limits<float>::max() : std::numeric_limits<float>::infinity();
  if (x < -kMax) return x > -0x1.ffffff0p127 ? -std::numeric_limits<float>::max() : -std::numeric_limits<float>::infinity();
  return static_cast<float>(x);
}

// The largest float <= x, and the smallest float >= x.
inline float toFloatDown(double x) {
  const float f = toFloat(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
inline float toFloatUp(double x) {
  const float f = toFloat(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace facet::ray
