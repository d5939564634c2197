#pragma once
// The few functions the shading code builds on, in the float operations of
// renderer/PIPELINE.md ("Arithmetic"), for one lane or four
// (lanes.h). Mirror: shaders/shading_math.glsl, the same names, the same
// operations in the same order. Only +, -, ·, /, sqrt, floor, comparisons,
// selects and bit casts: each is exact in IEEE single precision on both
// sides, so the results are the same bits.
#include "shading/lanes.h"

namespace facet {

// (a.x·b.x + a.y·b.y) + a.z·b.z
template <class V>
auto dot3(const V& a, const V& b) {
  return (a.x * b.x + a.y * b.y) + a.z * b.z;
}

// (a.y·b.z - a.z·b.y, a.z·b.x - a.x·b.z, a.x·b.y - a.y·b.x)
template <class V>
V cross3(const V& a, const V& b) {
  return V(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

// sqrt(v·v)
template <class V>
auto length3(const V& v) {
  return squareRoot(dot3(v, v));
}

// v · (1 / sqrt(v·v))
template <class V>
V normalize3(const V& v) {
  using F = decltype(v.x);
  const F s = F(1.0f) / squareRoot(dot3(v, v));
  return V(v.x * s, v.y * s, v.z * s);
}

// x > 0 ? x : 0, so NaN gives 0.
template <class F>
F maxZero(F x) {
  return select(x > F(0.0f), x, F(0.0f));
}

// x < 1 ? x : 1, so NaN gives 1.
template <class F>
F minOne(F x) {
  return select(x < F(1.0f), x, F(1.0f));
}

// [SECTION] x^y for the specular term: exp2(y·log2(x)) by the series below.
//
// log2(x): x = m·2^e with m in [1, 2) from the float's bits, then m in
// [√½, √2] (m/2, e+1 above √2); with s = (m - 1)/(m + 1),
// log2(m) = (2/ln 2)·(s + s³/3 + s⁵/5 + s⁷/7 + s⁹/9) by Horner in s².
// 2^t: i = floor(t), f = t - i in [0, 1), 2^f by its Taylor series to f⁹ by
// Horner, times 2^i made from the exponent bits. t below -126 gives 0 (no
// denormals: the fragment stage flushes them), t above 127 is taken as 127.
// Relative error below 10^-6 where the result is above 2^-9; x ≤ 0, NaN, or
// a NaN product y·log2(x) gives 0.
inline constexpr float kLog2Series[5] = {2.88539004f, 0.961796701f, 0.577078044f, 0.412198573f, 0.3205989f};
inline constexpr float kExp2Series[10] = {1.0f,           0.693147182f,    0.240226507f,    0.0555041097f,  0.00961812865f,
                                          0.00133335579f, 0.000154035297f, 1.52527336e-05f, 1.32154867e-06f, 1.01780863e-07f};
inline constexpr float kSqrtTwo = 1.41421354f;

// log2(x) for x > 0 by the series above (x ≤ 0 or NaN: not defined here; power guards it).
template <class F>
F log2Of(F x) {
  using I = IntOf<F>;
  const I bits = bitsOf(x);
  const F mantissa = floatOfBits((bits & I(0x007FFFFF)) | I(0x3F800000));
  const auto above = mantissa > F(kSqrtTwo);
  const F m = select(above, mantissa * F(0.5f), mantissa);
  const I e = select(above, (bits >> 23) - I(126), (bits >> 23) - I(127));
  const F s = (m - F(1.0f)) / (m + F(1.0f));
  const F s2 = s * s;
  F series = F(kLog2Series[4]);
  for (int k = 3; k >= 0; --k) series = F(kLog2Series[k]) + s2 * series;
  return toFloat(e) + s * series;
}

// 2^t by the series above: t below -126 (or NaN) gives 0, above 127 is taken as 127.
template <class F>
F exp2Of(F t) {
  using I = IntOf<F>;
  const auto inRange = t >= F(-126.0f);  // false for NaN
  const F clamped = select(t > F(127.0f), F(127.0f), select(inRange, t, F(0.0f)));
  const F whole = floorOf(clamped);
  const F f = clamped - whole;
  F exp2f = F(kExp2Series[9]);
  for (int k = 8; k >= 0; --k) exp2f = F(kExp2Series[k]) + f * exp2f;
  const F scale = floatOfBits((truncateToInt(whole) + I(127)) << 23);
  return select(inRange, exp2f * scale, F(0.0f));
}

template <class F>
F power(F x, F y) {
  const auto positive = x > F(0.0f);
  const F log2x = log2Of(select(positive, x, F(1.0f)));
  return select(positive, exp2Of(y * log2x), F(0.0f));
}

}  // namespace facet
