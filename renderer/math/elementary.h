#pragma once
// tan, atan, atan2 and acos, correctly rounded in float: facet's own, not
// the C library's, because the C library's are not the same everywhere.
// glibc 2.41 (Debian 13) took correctly rounded tanf, atanf, atan2f and
// acosf from the CORE-MATH project; glibc 2.36's (Debian 12) differ from
// them on 3.6 %, 6.2 %, 15.9 % and 7.7 % of random arguments, and so the
// camera's projection, its field of view and the ray tracer's sphere
// mapping changed between the two (renderer/PIPELINE.md, "One source of truth", has the
// measurements; sinf, cosf, expf, powf and the double functions are the
// same in both, bit for bit, and stay the C library's).
//
// Each is evaluated in double with + - · / and sqrt only (argument
// reduction by Cody and Waite's split constants, Taylor polynomials by
// Horner), so it gives the same bits on every IEEE-754 machine built with
// -ffp-contract=off; the float overloads round that double once, and agree
// with the correctly rounded value (long double's, rounded) on every
// argument tests/math/test_elementary.cpp draws. The double overloads are
// within a few units in the last place.
namespace facet::elementary {

double tan(double x);
double atan(double x);
double atan2(double y, double x);
double acos(double x);  // NaN outside [-1, 1]

inline float tan(float x) { return static_cast<float>(tan(static_cast<double>(x))); }
inline float atan(float x) { return static_cast<float>(atan(static_cast<double>(x))); }
inline float atan2(float y, float x) { return static_cast<float>(atan2(static_cast<double>(y), static_cast<double>(x))); }
inline float acos(float x) { return static_cast<float>(acos(static_cast<double>(x))); }

}  // namespace facet::elementary
