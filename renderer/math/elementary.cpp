#include "math/elementary.h"

// Only operations IEEE-754 defines exactly are taken from <cmath>: floor,
// fmod, fabs, sqrt, copysign and the classification tests.
#include <cmath>
#include <limits>

namespace facet::elementary {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// π and π/2 as a double and the rest that double leaves out.
constexpr double kPi = 3.141592653589793, kPiLow = 1.2246467991473532e-16;
constexpr double kHalfPi = 1.5707963267948966, kHalfPiLow = 6.123233995736766e-17;
constexpr double kQuarterPi = 0.7853981633974483;

// π/2 in three parts for the reduction (Cody and Waite; the values are
// fdlibm's pio2_1, pio2_2 and pio2_2t, e_rem_pio2.c): the first two have 33
// significant bits, so n·part is exact for |n| < 2^20.
constexpr double kHalfPi1 = 1.57079632673412561417e+00;
constexpr double kHalfPi2 = 6.07710050630396597660e-11;
constexpr double kHalfPi3 = 2.02226624879595063154e-21;
constexpr double kTwoOverPi = 6.36619772367581382433e-01;
// Past this the reduction loses accuracy (still the same bits everywhere);
// facet's angles are a few turns at most.
constexpr double kReductionLimit = 1 << 19;


// x = quadrant·π/2 + r with |r| ≤ π/4 (a little more past kReductionLimit).
struct Reduced {
  double r;
  int quadrant;  // 0 to 3
};

Reduced reduce(double x) {
  if (std::fabs(x) >= kReductionLimit) x = std::fmod(x, 2.0 * kPi);
  const double n = std::floor(x * kTwoOverPi + 0.5);
  const double r = ((x - n * kHalfPi1) - n * kHalfPi2) - n * kHalfPi3;
  const double q = n - 4.0 * std::floor(n * 0.25);
  return {r, static_cast<int>(q)};
}

// Taylor polynomials of sin and cos on [-π/4, π/4], to the terms below
// 2^-60 there: 1/n! with alternating signs, by Horner in r². tan is their
// quotient.
double sinPolynomial(double r) {
  const double z = r * r;
  const double p =
      -0.16666666666666666 +
      z * (0.008333333333333333 +
           z * (-0.0001984126984126984 +
                z * (2.7557319223985893e-06 +
                     z * (-2.505210838544172e-08 +
                          z * (1.6059043836821613e-10 + z * (-7.647163731819816e-13 + z * (2.8114572543455206e-15 + z * -8.22063524662433e-18)))))));
  return r + r * (z * p);
}

double cosPolynomial(double r) {
  const double z = r * r;
  const double p =
      0.041666666666666664 +
      z * (-0.001388888888888889 +
           z * (2.48015873015873e-05 +
                z * (-2.755731922398589e-07 +
                     z * (2.08767569878681e-09 + z * (-1.1470745597729725e-11 + z * (4.779477332387385e-14 + z * -1.5619206968586225e-16))))));
  return 1.0 + z * (-0.5 + z * p);
}

// atan(t) for 0 ≤ t ≤ tan(π/16) ≈ 0.199: t - t³/3 + t⁵/5 - ..., to t^27.
double atanSeries(double t) {
  const double z = t * t;
  const double p =
      -0.3333333333333333 +
      z * (0.2 +
           z * (-0.14285714285714285 +
                z * (0.1111111111111111 +
                     z * (-0.09090909090909091 +
                          z * (0.07692307692307693 +
                               z * (-0.06666666666666667 +
                                    z * (0.058823529411764705 +
                                         z * (-0.05263157894736842 +
                                              z * (0.047619047619047616 + z * (-0.043478260869565216 + z * (0.04 + z * -0.037037037037037035)))))))))));
  return t + t * (z * p);
}

}  // namespace

double tan(double x) {
  if (!std::isfinite(x)) return kNaN;
  if (x == 0.0) return x;  // ±0 as given (the polynomial would give +0 for -0)
  const Reduced a = reduce(x);
  const double s = sinPolynomial(a.r), c = cosPolynomial(a.r);
  return a.quadrant % 2 == 0 ? s / c : -c / s;
}

double atan(double x) {
  if (std::isnan(x)) return x;
  const double a = std::fabs(x);
  // atan(a) = π/2 - atan(1/a) above 1; then two halvings of the angle,
  // atan(t) = 2·atan(t / (1 + √(1 + t²))), bring t below tan(π/16).
  double t = a > 1.0 ? 1.0 / a : a;
  t = t / (1.0 + std::sqrt(1.0 + t * t));
  t = t / (1.0 + std::sqrt(1.0 + t * t));
  const double angle = 4.0 * atanSeries(t);
  const double result = a > 1.0 ? (kHalfPi - angle) + kHalfPiLow : angle;
  return std::copysign(result, x);
}

double atan2(double y, double x) {
  if (std::isnan(x) || std::isnan(y)) return x + y;
  if (y == 0.0) return std::signbit(x) ? std::copysign(kPi, y) : y;
  if (x == 0.0) return std::copysign(kHalfPi, y);
  if (std::isinf(x)) {
    if (std::isinf(y)) return std::copysign(x > 0 ? kQuarterPi : 3.0 * kQuarterPi, y);
    return x > 0 ? std::copysign(0.0, y) : std::copysign(kPi, y);
  }
  if (std::isinf(y)) return std::copysign(kHalfPi, y);
  const double angle = atan(std::fabs(y / x));
  return std::copysign(x > 0 ? angle : (kPi - angle) + kPiLow, y);
}

double acos(double x) {
  if (!(std::fabs(x) <= 1.0)) return kNaN;
  return atan2(std::sqrt((1.0 - x) * (1.0 + x)), x);
}

}  // namespace facet::elementary
