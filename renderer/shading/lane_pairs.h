#pragma once
// Two registers of a lane type shaded side by side: Twice<Float16> is 32
// lanes, each operation done on lanes [0, 16) and then on [16, 32). The
// result is the lane type's, lane by lane, so the same bits. What it buys is
// time: one batch's shading is a single chain of dependent operations (the
// `power` series' Horner steps, three normalizations, each waiting on the
// one before), and two independent chains written next to each other let
// the CPU run one while the other waits. Only the lanes' own operations are
// here; the look-ups that read memory lane by lane (shadow maps, the
// environment map) take each half in turn (lighting.h).
#include <type_traits>

#include "shading/lanes.h"

namespace facet {

template <class T>
struct Twice {
  T a, b;  // the low and the high half of the lanes
  Twice() = default;
  Twice(T low, T high) : a(low), b(high) {}
  template <class S>
    requires std::is_arithmetic_v<S>
  Twice(S value) : a(value), b(value) {}  // a constant in every lane
};

template <class T>
Twice<T> operator+(const Twice<T>& x, const Twice<T>& y) { return {x.a + y.a, x.b + y.b}; }
template <class T>
Twice<T> operator-(const Twice<T>& x, const Twice<T>& y) { return {x.a - y.a, x.b - y.b}; }
template <class T>
Twice<T> operator*(const Twice<T>& x, const Twice<T>& y) { return {x.a * y.a, x.b * y.b}; }
template <class T>
Twice<T> operator/(const Twice<T>& x, const Twice<T>& y) { return {x.a / y.a, x.b / y.b}; }
template <class T>
Twice<T> operator-(const Twice<T>& x) { return {-x.a, -x.b}; }
template <class T>
Twice<T> operator&(const Twice<T>& x, const Twice<T>& y) { return {x.a & y.a, x.b & y.b}; }
template <class T>
Twice<T> operator|(const Twice<T>& x, const Twice<T>& y) { return {x.a | y.a, x.b | y.b}; }
template <class T>
Twice<T> operator!(const Twice<T>& x) { return {!x.a, !x.b}; }
template <class T>
Twice<T> operator>>(const Twice<T>& x, int n) { return {x.a >> n, x.b >> n}; }
template <class T>
Twice<T> operator<<(const Twice<T>& x, int n) { return {x.a << n, x.b << n}; }
template <class T>
auto operator<(const Twice<T>& x, const Twice<T>& y) { return Twice<decltype(x.a < y.a)>{x.a < y.a, x.b < y.b}; }
template <class T>
auto operator>(const Twice<T>& x, const Twice<T>& y) { return Twice<decltype(x.a > y.a)>{x.a > y.a, x.b > y.b}; }
template <class T>
auto operator<=(const Twice<T>& x, const Twice<T>& y) { return Twice<decltype(x.a <= y.a)>{x.a <= y.a, x.b <= y.b}; }
template <class T>
auto operator>=(const Twice<T>& x, const Twice<T>& y) { return Twice<decltype(x.a >= y.a)>{x.a >= y.a, x.b >= y.b}; }
template <class M, class T>
Twice<T> select(const Twice<M>& mask, const Twice<T>& x, const Twice<T>& y) { return {select(mask.a, x.a, y.a), select(mask.b, x.b, y.b)}; }
template <class M>
Twice<M> both(const Twice<M>& x, const Twice<M>& y) { return {both(x.a, y.a), both(x.b, y.b)}; }
template <class M>
bool anyLane(const Twice<M>& mask) { return anyLane(mask.a) || anyLane(mask.b); }
template <class T>
Twice<T> squareRoot(const Twice<T>& x) { return {squareRoot(x.a), squareRoot(x.b)}; }
template <class T>
Twice<T> absOf(const Twice<T>& x) { return {absOf(x.a), absOf(x.b)}; }
template <class T>
Twice<T> floorOf(const Twice<T>& x) { return {floorOf(x.a), floorOf(x.b)}; }
template <class T>
auto bitsOf(const Twice<T>& x) { return Twice<decltype(bitsOf(x.a))>{bitsOf(x.a), bitsOf(x.b)}; }
template <class T>
auto floatOfBits(const Twice<T>& i) { return Twice<decltype(floatOfBits(i.a))>{floatOfBits(i.a), floatOfBits(i.b)}; }
template <class T>
auto toFloat(const Twice<T>& i) { return Twice<decltype(toFloat(i.a))>{toFloat(i.a), toFloat(i.b)}; }
template <class T>
auto truncateToInt(const Twice<T>& x) { return Twice<decltype(truncateToInt(x.a))>{truncateToInt(x.a), truncateToInt(x.b)}; }
template <class T>
auto equalLanes(const Twice<T>& x, const Twice<T>& y) { return Twice<decltype(equalLanes(x.a, y.a))>{equalLanes(x.a, y.a), equalLanes(x.b, y.b)}; }

// Three components of twice a lane type's lanes: glm::vec3's operations, lane by lane.
template <class F>
struct TwiceVec3 {
  Twice<F> x, y, z;
  TwiceVec3() = default;
  TwiceVec3(Twice<F> a, Twice<F> b, Twice<F> c) : x(a), y(b), z(c) {}
  explicit TwiceVec3(glm::vec3 v) : x(v.x), y(v.y), z(v.z) {}  // the same vector in every lane
  Vec3Of<F> half(int h) const { return h == 0 ? Vec3Of<F>(x.a, y.a, z.a) : Vec3Of<F>(x.b, y.b, z.b); }
};
template <class F>
TwiceVec3<F> operator+(const TwiceVec3<F>& p, const TwiceVec3<F>& q) { return {p.x + q.x, p.y + q.y, p.z + q.z}; }
template <class F>
TwiceVec3<F> operator-(const TwiceVec3<F>& p, const TwiceVec3<F>& q) { return {p.x - q.x, p.y - q.y, p.z - q.z}; }
template <class F>
TwiceVec3<F> operator-(const TwiceVec3<F>& p) { return {-p.x, -p.y, -p.z}; }
template <class F>
TwiceVec3<F> operator*(const Twice<F>& s, const TwiceVec3<F>& v) { return {s * v.x, s * v.y, s * v.z}; }
template <class F>
TwiceVec3<F> operator*(const TwiceVec3<F>& v, const Twice<F>& s) { return {v.x * s, v.y * s, v.z * s}; }
template <class F>
TwiceVec3<F> operator*(const TwiceVec3<F>& p, const TwiceVec3<F>& q) { return {p.x * q.x, p.y * q.y, p.z * q.z}; }
template <class F>
TwiceVec3<F> operator/(const TwiceVec3<F>& v, const Twice<F>& s) { return {v.x / s, v.y / s, v.z / s}; }
template <class M, class F>
TwiceVec3<F> select(const Twice<M>& mask, const TwiceVec3<F>& p, const TwiceVec3<F>& q) {
  return {select(mask, p.x, q.x), select(mask, p.y, q.y), select(mask, p.z, q.z)};
}
template <class F>
TwiceVec3<F> joinedTwice(const Vec3Of<F>& low, const Vec3Of<F>& high) {
  return {{low.x, high.x}, {low.y, high.y}, {low.z, high.z}};
}

template <class F>
struct LaneTypes<Twice<F>> {
  using Vec3 = TwiceVec3<F>;
  using Int = Twice<IntOf<F>>;
  using Mask = Twice<MaskOf<F>>;
};

// How many lanes a mask type covers.
template <class M>
inline constexpr int kMaskLanes = 0;
#if defined(__SSE2__)
template <>
inline constexpr int kMaskLanes<Mask4> = 4;
#endif
#if defined(__AVX2__)
template <>
inline constexpr int kMaskLanes<Mask8> = 8;
#endif
#if defined(__AVX512F__)
template <>
inline constexpr int kMaskLanes<Mask16> = 16;
#endif

// The lanes' bits: the low half's, then the high half's above them.
template <class M>
int laneBits(const Twice<M>& mask) {
  static_assert(kMaskLanes<M> > 0);
  return laneBits(mask.a) | laneBits(mask.b) << kMaskLanes<M>;
}

// Lanes from / to floats (or ints) aligned as the lane type's loads want them.
template <class T, class S>
void loadLanes(Twice<T>& x, const S* p) {
  loadLanes(x.a, p);
  loadLanes(x.b, p + kLaneCount<T>);
}
template <class T, class S>
void storeLanes(S* p, const Twice<T>& x) {
  storeLanes(p, x.a);
  storeLanes(p + kLaneCount<T>, x.b);
}
// loadPixels and storePixels on each half.
template <class F>
void loadPixels(const float* rgba, const std::size_t* offsets, int count, TwiceVec3<F>& color, Twice<F>& alpha) {
  constexpr int kHalf = kLaneCount<F>;
  Vec3Of<F> low, high;
  loadPixels(rgba, offsets, count, low, alpha.a);
  loadPixels(rgba, offsets + kHalf, count - kHalf, high, alpha.b);
  color = joinedTwice<F>(low, high);
}
template <class F>
void storePixels(float* rgba, const std::size_t* offsets, int count, const TwiceVec3<F>& color, const Twice<F>& alpha) {
  constexpr int kHalf = kLaneCount<F>;
  storePixels(rgba, offsets, count, color.half(0), alpha.a);
  storePixels(rgba, offsets + kHalf, count - kHalf, color.half(1), alpha.b);
}

}  // namespace facet
