#pragma once
// The shading code is written once (shading_math.h, lighting.h) and runs on
// one pixel or on four, eight or sixteen at a time. This header gives it the
// lane types: for one pixel, float, bool, std::int32_t and glm::vec3; for
// four, Float4, Mask4, Int4 and Vec3x4 over SSE2; for eight, Float8, Mask8,
// Int8 and Vec3x8 over AVX2, in the translation units built for AVX2
// (phong_batch_avx2.cpp, phong_batch_avx512.cpp); for sixteen, Float16,
// Mask16, Int16 and Vec3x16 over AVX-512F, in the one built for it
// (phong_batch_avx512.cpp). Every lane operation is the IEEE operation of
// the one-pixel type lane by lane (no fused multiply-add, no approximate
// reciprocal), so all four give the same bits. Where SSE2 is missing, only
// the one-pixel types exist.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__AVX2__) || defined(__AVX512F__) || defined(__FMA__)
#include <immintrin.h>
#endif

namespace facet {

// The 4x4 transpose in each 128-bit part of four registers of lane type F
// (_MM_TRANSPOSE4_PS's steps, at eight or sixteen lanes): RGBA pixels to
// lanes of r, g, b and a, and back (loadPixels, storePixels). F's register
// operations come from Shuffles<F>, given below for Float8 and Float16.
template <class F>
struct Shuffles;
template <class F>
void transposeQuarters(F (&p)[4]) {
  using S = Shuffles<F>;
  const F t0 = S::low(p[0], p[1]), t1 = S::low(p[2], p[3]), t2 = S::high(p[0], p[1]), t3 = S::high(p[2], p[3]);
  p[0] = S::template pick<0x44>(t0, t1), p[1] = S::template pick<0xEE>(t0, t1);
  p[2] = S::template pick<0x44>(t2, t3), p[3] = S::template pick<0xEE>(t2, t3);
}

// [SECTION] One lane: the operations the generic code calls by name.

// a·b + c with one rounding. The rule is the fused operation; on CPUs with
// FMA (llvmpipe fuses there) the build uses the instruction, elsewhere the C
// library computes it exactly.
inline float fusedMultiplyAdd(float a, float b, float c) { return std::fma(a, b, c); }

// x86's minps / maxps on one value: (a < b) ? a : b and (a > b) ? a : b, so
// a NaN in a gives b.
inline float minX86(float a, float b) { return a < b ? a : b; }
inline float maxX86(float a, float b) { return a > b ? a : b; }

inline float select(bool mask, float a, float b) { return mask ? a : b; }
inline std::int32_t select(bool mask, std::int32_t a, std::int32_t b) { return mask ? a : b; }
inline glm::vec3 select(bool mask, glm::vec3 a, glm::vec3 b) { return mask ? a : b; }
inline bool anyLane(bool mask) { return mask; }
inline bool both(bool a, bool b) { return a && b; }
inline float squareRoot(float x) { return std::sqrt(x); }
inline float floorOf(float x) { return std::floor(x); }
inline std::int32_t bitsOf(float x) {
  std::int32_t i;
  static_assert(sizeof i == sizeof x);
  __builtin_memcpy(&i, &x, sizeof i);
  return i;
}
inline float floatOfBits(std::int32_t i) {
  float x;
  __builtin_memcpy(&x, &i, sizeof x);
  return x;
}
inline float toFloat(std::int32_t i) { return static_cast<float>(i); }
inline std::int32_t truncateToInt(float x) { return static_cast<std::int32_t>(x); }  // |x| < 2^31

#if defined(__SSE2__)
// fusedMultiplyAdd on four lanes.
inline __m128 fusedMultiplyAdd4(__m128 a, __m128 b, __m128 c) {
#if defined(__FMA__)
  return _mm_fmadd_ps(a, b, c);
#else
  alignas(16) float x[4], y[4], z[4];
  _mm_store_ps(x, a), _mm_store_ps(y, b), _mm_store_ps(z, c);
  for (int k = 0; k < 4; ++k) x[k] = fusedMultiplyAdd(x[k], y[k], z[k]);
  return _mm_load_ps(x);
#endif
}

#endif

#if defined(__SSE2__)

// [SECTION] Four lanes.

struct Mask4 {
  __m128 m;  // all ones or all zeros per lane
};
inline Mask4 operator&(Mask4 a, Mask4 b) { return {_mm_and_ps(a.m, b.m)}; }
inline Mask4 operator|(Mask4 a, Mask4 b) { return {_mm_or_ps(a.m, b.m)}; }
inline Mask4 operator!(Mask4 a) { return {_mm_xor_ps(a.m, _mm_castsi128_ps(_mm_set1_epi32(-1)))}; }
inline Mask4 both(Mask4 a, Mask4 b) { return a & b; }
inline bool anyLane(Mask4 a) { return _mm_movemask_ps(a.m) != 0; }
inline int laneBits(Mask4 a) { return _mm_movemask_ps(a.m); }

struct Float4 {
  __m128 v;
  Float4() = default;
  explicit Float4(__m128 value) : v(value) {}
  Float4(float value) : v(_mm_set1_ps(value)) {}  // a constant in every lane, as a float literal in the one-lane code
};
inline Float4 operator+(Float4 a, Float4 b) { return Float4(_mm_add_ps(a.v, b.v)); }
inline Float4 operator-(Float4 a, Float4 b) { return Float4(_mm_sub_ps(a.v, b.v)); }
inline Float4 operator*(Float4 a, Float4 b) { return Float4(_mm_mul_ps(a.v, b.v)); }
inline Float4 operator/(Float4 a, Float4 b) { return Float4(_mm_div_ps(a.v, b.v)); }
inline Float4 operator-(Float4 a) { return Float4(_mm_xor_ps(a.v, _mm_set1_ps(-0.0f))); }  // the sign bit, as float's unary minus
inline Mask4 operator<(Float4 a, Float4 b) { return {_mm_cmplt_ps(a.v, b.v)}; }
inline Mask4 operator>(Float4 a, Float4 b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
inline Mask4 operator<=(Float4 a, Float4 b) { return {_mm_cmple_ps(a.v, b.v)}; }
inline Mask4 operator>=(Float4 a, Float4 b) { return {_mm_cmpge_ps(a.v, b.v)}; }
inline Float4 select(Mask4 mask, Float4 a, Float4 b) { return Float4(_mm_or_ps(_mm_and_ps(mask.m, a.v), _mm_andnot_ps(mask.m, b.v))); }
inline Float4 squareRoot(Float4 x) { return Float4(_mm_sqrt_ps(x.v)); }
inline Float4 fusedMultiplyAdd(Float4 a, Float4 b, Float4 c) { return Float4(fusedMultiplyAdd4(a.v, b.v, c.v)); }  // fusedMultiplyAdd's
inline Float4 absOf(Float4 x) { return Float4(_mm_andnot_ps(_mm_set1_ps(-0.0f), x.v)); }  // the sign bit cleared

struct Int4 {
  __m128i v;
  Int4() = default;
  explicit Int4(__m128i value) : v(value) {}
  Int4(std::int32_t value) : v(_mm_set1_epi32(value)) {}
};
inline Int4 operator+(Int4 a, Int4 b) { return Int4(_mm_add_epi32(a.v, b.v)); }
inline Int4 operator-(Int4 a, Int4 b) { return Int4(_mm_sub_epi32(a.v, b.v)); }
inline Int4 operator&(Int4 a, Int4 b) { return Int4(_mm_and_si128(a.v, b.v)); }
inline Int4 operator|(Int4 a, Int4 b) { return Int4(_mm_or_si128(a.v, b.v)); }
inline Int4 operator>>(Int4 a, int n) { return Int4(_mm_srai_epi32(a.v, n)); }
inline Int4 operator<<(Int4 a, int n) { return Int4(_mm_slli_epi32(a.v, n)); }
inline Int4 select(Mask4 mask, Int4 a, Int4 b) {
  const __m128i m = _mm_castps_si128(mask.m);
  return Int4(_mm_or_si128(_mm_and_si128(m, a.v), _mm_andnot_si128(m, b.v)));
}
inline Int4 bitsOf(Float4 x) { return Int4(_mm_castps_si128(x.v)); }
inline Float4 floatOfBits(Int4 i) { return Float4(_mm_castsi128_ps(i.v)); }
inline Float4 toFloat(Int4 i) { return Float4(_mm_cvtepi32_ps(i.v)); }
inline Int4 truncateToInt(Float4 x) { return Int4(_mm_cvttps_epi32(x.v)); }
inline Mask4 equalLanes(Int4 a, Int4 b) { return {_mm_castsi128_ps(_mm_cmpeq_epi32(a.v, b.v))}; }
inline void storeLanes(std::int32_t* p, Int4 i) { _mm_store_si128(reinterpret_cast<__m128i*>(p), i.v); }  // aligned to 16 bytes
// floor for |x| < 2^31: truncate, then one less where that went up (negative non-integers).
inline Float4 floorOf(Float4 x) {
  const Float4 t = toFloat(truncateToInt(x));
  return select(x < t, t - Float4(1.0f), t);
}

// Three components of four lanes: glm::vec3's operations, lane by lane.
struct Vec3x4 {
  Float4 x, y, z;
  Vec3x4() = default;
  Vec3x4(Float4 a, Float4 b, Float4 c) : x(a), y(b), z(c) {}
  explicit Vec3x4(glm::vec3 v) : x(v.x), y(v.y), z(v.z) {}  // the same vector in every lane
};
inline Vec3x4 operator+(const Vec3x4& a, const Vec3x4& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3x4 operator-(const Vec3x4& a, const Vec3x4& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3x4 operator-(const Vec3x4& a) { return {-a.x, -a.y, -a.z}; }
inline Vec3x4 operator*(Float4 s, const Vec3x4& v) { return {s * v.x, s * v.y, s * v.z}; }
inline Vec3x4 operator*(const Vec3x4& v, Float4 s) { return {v.x * s, v.y * s, v.z * s}; }
inline Vec3x4 operator*(const Vec3x4& a, const Vec3x4& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline Vec3x4 operator/(const Vec3x4& v, Float4 s) { return {v.x / s, v.y / s, v.z / s}; }
inline Vec3x4 select(Mask4 mask, const Vec3x4& a, const Vec3x4& b) { return {select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z)}; }
// Four lanes from / to four floats aligned to 16 bytes.
inline void loadLanes(Float4& x, const float* p) { x = Float4(_mm_load_ps(p)); }
inline void storeLanes(float* p, Float4 x) { _mm_store_ps(p, x.v); }
// Four lanes from / to four floats at any address.
inline void loadLanesUnaligned(Float4& x, const float* p) { x = Float4(_mm_loadu_ps(p)); }
inline void storeLanesUnaligned(float* p, Float4 x) { _mm_storeu_ps(p, x.v); }
// The RGBA pixels at rgba + 4·offsets[k], k < count, as lanes of colour and
// alpha, and back: a transpose in registers and one 16-byte load or store a
// pixel. Lanes past count read 0 and write nothing. (Storing the lanes and
// reading them back a float at a time waits on store forwarding: 7 % of a
// blended full-screen frame.)
inline void loadPixels(const float* rgba, const std::size_t* offsets, int count, Vec3x4& color, Float4& alpha) {
  __m128 pixel[4];
  for (int k = 0; k < 4; ++k) pixel[k] = k < count ? _mm_loadu_ps(rgba + 4 * offsets[k]) : _mm_setzero_ps();
  _MM_TRANSPOSE4_PS(pixel[0], pixel[1], pixel[2], pixel[3]);
  color = {Float4(pixel[0]), Float4(pixel[1]), Float4(pixel[2])}, alpha = Float4(pixel[3]);
}
inline void storePixels(float* rgba, const std::size_t* offsets, int count, const Vec3x4& color, Float4 alpha) {
  __m128 pixel[4] = {color.x.v, color.y.v, color.z.v, alpha.v};
  _MM_TRANSPOSE4_PS(pixel[0], pixel[1], pixel[2], pixel[3]);
  for (int k = 0; k < 4 && k < count; ++k) _mm_storeu_ps(rgba + 4 * offsets[k], pixel[k]);
}

#endif

#if defined(__AVX2__)

// [SECTION] Eight lanes: the four-lane operations on 256-bit registers.

struct Mask8 {
  __m256 m;  // all ones or all zeros per lane
};
inline Mask8 operator&(Mask8 a, Mask8 b) { return {_mm256_and_ps(a.m, b.m)}; }
inline Mask8 operator|(Mask8 a, Mask8 b) { return {_mm256_or_ps(a.m, b.m)}; }
inline Mask8 operator!(Mask8 a) { return {_mm256_xor_ps(a.m, _mm256_castsi256_ps(_mm256_set1_epi32(-1)))}; }
inline Mask8 both(Mask8 a, Mask8 b) { return a & b; }
inline bool anyLane(Mask8 a) { return _mm256_movemask_ps(a.m) != 0; }
inline int laneBits(Mask8 a) { return _mm256_movemask_ps(a.m); }

struct Float8 {
  __m256 v;
  Float8() = default;
  explicit Float8(__m256 value) : v(value) {}
  Float8(float value) : v(_mm256_set1_ps(value)) {}
};
inline Float8 operator+(Float8 a, Float8 b) { return Float8(_mm256_add_ps(a.v, b.v)); }
inline Float8 operator-(Float8 a, Float8 b) { return Float8(_mm256_sub_ps(a.v, b.v)); }
inline Float8 operator*(Float8 a, Float8 b) { return Float8(_mm256_mul_ps(a.v, b.v)); }
inline Float8 operator/(Float8 a, Float8 b) { return Float8(_mm256_div_ps(a.v, b.v)); }
inline Float8 operator-(Float8 a) { return Float8(_mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f))); }
// The ordered predicates: false where either side is NaN, as SSE's cmplt..cmpge and float's comparisons.
inline Mask8 operator<(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OS)}; }
inline Mask8 operator>(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OS)}; }
inline Mask8 operator<=(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LE_OS)}; }
inline Mask8 operator>=(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GE_OS)}; }
inline Float8 select(Mask8 mask, Float8 a, Float8 b) { return Float8(_mm256_blendv_ps(b.v, a.v, mask.m)); }
inline Float8 squareRoot(Float8 x) { return Float8(_mm256_sqrt_ps(x.v)); }
// a·b + c with one rounding per lane (fusedMultiplyAdd's): the instruction where the
// build has FMA, else the C library's exact one lane by lane.
inline Float8 fusedMultiplyAdd(Float8 a, Float8 b, Float8 c) {
#if defined(__FMA__)
  return Float8(_mm256_fmadd_ps(a.v, b.v, c.v));
#else
  alignas(32) float x[8], y[8], z[8];
  _mm256_store_ps(x, a.v), _mm256_store_ps(y, b.v), _mm256_store_ps(z, c.v);
  for (int k = 0; k < 8; ++k) x[k] = std::fma(x[k], y[k], z[k]);
  return Float8(_mm256_load_ps(x));
#endif
}
inline Float8 absOf(Float8 x) { return Float8(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), x.v)); }

struct Int8 {
  __m256i v;
  Int8() = default;
  explicit Int8(__m256i value) : v(value) {}
  Int8(std::int32_t value) : v(_mm256_set1_epi32(value)) {}
};
inline Int8 operator+(Int8 a, Int8 b) { return Int8(_mm256_add_epi32(a.v, b.v)); }
inline Int8 operator-(Int8 a, Int8 b) { return Int8(_mm256_sub_epi32(a.v, b.v)); }
inline Int8 operator&(Int8 a, Int8 b) { return Int8(_mm256_and_si256(a.v, b.v)); }
inline Int8 operator|(Int8 a, Int8 b) { return Int8(_mm256_or_si256(a.v, b.v)); }
inline Int8 operator>>(Int8 a, int n) { return Int8(_mm256_srai_epi32(a.v, n)); }
inline Int8 operator<<(Int8 a, int n) { return Int8(_mm256_slli_epi32(a.v, n)); }
inline Int8 select(Mask8 mask, Int8 a, Int8 b) { return Int8(_mm256_blendv_epi8(b.v, a.v, _mm256_castps_si256(mask.m))); }
inline Int8 bitsOf(Float8 x) { return Int8(_mm256_castps_si256(x.v)); }
inline Float8 floatOfBits(Int8 i) { return Float8(_mm256_castsi256_ps(i.v)); }
inline Float8 toFloat(Int8 i) { return Float8(_mm256_cvtepi32_ps(i.v)); }
inline Int8 truncateToInt(Float8 x) { return Int8(_mm256_cvttps_epi32(x.v)); }
inline Mask8 equalLanes(Int8 a, Int8 b) { return {_mm256_castsi256_ps(_mm256_cmpeq_epi32(a.v, b.v))}; }
inline void storeLanes(std::int32_t* p, Int8 i) { _mm256_store_si256(reinterpret_cast<__m256i*>(p), i.v); }  // aligned to 32 bytes
inline Float8 floorOf(Float8 x) {  // as Float4's: truncate, then one less where that went up
  const Float8 t = toFloat(truncateToInt(x));
  return select(x < t, t - Float8(1.0f), t);
}

struct Vec3x8 {
  Float8 x, y, z;
  Vec3x8() = default;
  Vec3x8(Float8 a, Float8 b, Float8 c) : x(a), y(b), z(c) {}
  explicit Vec3x8(glm::vec3 v) : x(v.x), y(v.y), z(v.z) {}
};
inline Vec3x8 operator+(const Vec3x8& a, const Vec3x8& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3x8 operator-(const Vec3x8& a, const Vec3x8& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3x8 operator-(const Vec3x8& a) { return {-a.x, -a.y, -a.z}; }
inline Vec3x8 operator*(Float8 s, const Vec3x8& v) { return {s * v.x, s * v.y, s * v.z}; }
inline Vec3x8 operator*(const Vec3x8& v, Float8 s) { return {v.x * s, v.y * s, v.z * s}; }
inline Vec3x8 operator*(const Vec3x8& a, const Vec3x8& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline Vec3x8 operator/(const Vec3x8& v, Float8 s) { return {v.x / s, v.y / s, v.z / s}; }
inline Vec3x8 select(Mask8 mask, const Vec3x8& a, const Vec3x8& b) { return {select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z)}; }
// Eight lanes from / to eight floats aligned to 32 bytes.
inline void loadLanes(Float8& x, const float* p) { x = Float8(_mm256_load_ps(p)); }
inline void storeLanes(float* p, Float8 x) { _mm256_store_ps(p, x.v); }
inline void loadLanesUnaligned(Float8& x, const float* p) { x = Float8(_mm256_loadu_ps(p)); }
inline void storeLanesUnaligned(float* p, Float8 x) { _mm256_storeu_ps(p, x.v); }
// unpacklo, unpackhi and shuffle on eight lanes, for transposeQuarters.
template <>
struct Shuffles<Float8> {
  static Float8 low(Float8 a, Float8 b) { return Float8(_mm256_unpacklo_ps(a.v, b.v)); }
  static Float8 high(Float8 a, Float8 b) { return Float8(_mm256_unpackhi_ps(a.v, b.v)); }
  template <int kPick>
  static Float8 pick(Float8 a, Float8 b) { return Float8(_mm256_shuffle_ps(a.v, b.v, kPick)); }
};
// loadPixels and storePixels on eight lanes: register k holds pixel k in its
// low half and pixel k + 4 in its high half, so that the transpose, done in
// both halves at once, leaves lanes 0-3 low and 4-7 high.
inline void loadPixels(const float* rgba, const std::size_t* offsets, int count, Vec3x8& color, Float8& alpha) {
  const auto at = [&](int k) { return k < count ? _mm_loadu_ps(rgba + 4 * offsets[k]) : _mm_setzero_ps(); };
  Float8 pixel[4];
  for (int k = 0; k < 4; ++k) pixel[k] = Float8(_mm256_set_m128(at(k + 4), at(k)));
  transposeQuarters(pixel);
  color = {pixel[0], pixel[1], pixel[2]}, alpha = pixel[3];
}
inline void storePixels(float* rgba, const std::size_t* offsets, int count, const Vec3x8& color, Float8 alpha) {
  Float8 pixel[4] = {color.x, color.y, color.z, alpha};
  transposeQuarters(pixel);
  for (int k = 0; k < 4; ++k) {
    if (k < count) _mm_storeu_ps(rgba + 4 * offsets[k], _mm256_castps256_ps128(pixel[k].v));
    if (k + 4 < count) _mm_storeu_ps(rgba + 4 * offsets[k + 4], _mm256_extractf128_ps(pixel[k].v, 1));
  }
}

// The four low lanes (half 0) or high lanes (half 1), for code written for four lanes.
inline Float4 halfOf(Float8 a, int half) { return Float4(half == 0 ? _mm256_castps256_ps128(a.v) : _mm256_extractf128_ps(a.v, 1)); }
inline Mask4 halfOf(Mask8 a, int half) { return {half == 0 ? _mm256_castps256_ps128(a.m) : _mm256_extractf128_ps(a.m, 1)}; }
inline Vec3x4 halfOf(const Vec3x8& a, int half) { return {halfOf(a.x, half), halfOf(a.y, half), halfOf(a.z, half)}; }
inline Float8 joined(Float4 low, Float4 high) { return Float8(_mm256_set_m128(high.v, low.v)); }
inline Vec3x8 joined(const Vec3x4& low, const Vec3x4& high) { return {joined(low.x, high.x), joined(low.y, high.y), joined(low.z, high.z)}; }

#endif

#if defined(__AVX512F__)

// [SECTION] Sixteen lanes: the eight-lane operations on 512-bit registers.
// AVX-512F alone (no DQ, no VL): the bit operations on floats go through the
// integer ones, and a mask is the comparison's 16-bit mask register.

struct Mask16 {
  __mmask16 m;  // one bit per lane
};
inline Mask16 operator&(Mask16 a, Mask16 b) { return {static_cast<__mmask16>(a.m & b.m)}; }
inline Mask16 operator|(Mask16 a, Mask16 b) { return {static_cast<__mmask16>(a.m | b.m)}; }
inline Mask16 operator!(Mask16 a) { return {static_cast<__mmask16>(~a.m)}; }
inline Mask16 both(Mask16 a, Mask16 b) { return a & b; }
inline bool anyLane(Mask16 a) { return a.m != 0; }
inline int laneBits(Mask16 a) { return a.m; }

struct Float16 {
  __m512 v;
  Float16() = default;
  explicit Float16(__m512 value) : v(value) {}
  Float16(float value) : v(_mm512_set1_ps(value)) {}
};
inline Float16 operator+(Float16 a, Float16 b) { return Float16(_mm512_add_ps(a.v, b.v)); }
inline Float16 operator-(Float16 a, Float16 b) { return Float16(_mm512_sub_ps(a.v, b.v)); }
inline Float16 operator*(Float16 a, Float16 b) { return Float16(_mm512_mul_ps(a.v, b.v)); }
inline Float16 operator/(Float16 a, Float16 b) { return Float16(_mm512_div_ps(a.v, b.v)); }
inline Float16 operator-(Float16 a) {  // the sign bit
  return Float16(_mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(a.v), _mm512_set1_epi32(static_cast<std::int32_t>(0x80000000u)))));
}
// The ordered predicates, as Float8's.
inline Mask16 operator<(Float16 a, Float16 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LT_OS)}; }
inline Mask16 operator>(Float16 a, Float16 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_GT_OS)}; }
inline Mask16 operator<=(Float16 a, Float16 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LE_OS)}; }
inline Mask16 operator>=(Float16 a, Float16 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_GE_OS)}; }
inline Float16 select(Mask16 mask, Float16 a, Float16 b) { return Float16(_mm512_mask_blend_ps(mask.m, b.v, a.v)); }
inline Float16 squareRoot(Float16 x) { return Float16(_mm512_sqrt_ps(x.v)); }
inline Float16 fusedMultiplyAdd(Float16 a, Float16 b, Float16 c) { return Float16(_mm512_fmadd_ps(a.v, b.v, c.v)); }  // AVX-512F's own
inline Float16 absOf(Float16 x) { return Float16(_mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(x.v), _mm512_set1_epi32(0x7FFFFFFF)))); }

struct Int16 {
  __m512i v;
  Int16() = default;
  explicit Int16(__m512i value) : v(value) {}
  Int16(std::int32_t value) : v(_mm512_set1_epi32(value)) {}
};
inline Int16 operator+(Int16 a, Int16 b) { return Int16(_mm512_add_epi32(a.v, b.v)); }
inline Int16 operator-(Int16 a, Int16 b) { return Int16(_mm512_sub_epi32(a.v, b.v)); }
inline Int16 operator&(Int16 a, Int16 b) { return Int16(_mm512_and_si512(a.v, b.v)); }
inline Int16 operator|(Int16 a, Int16 b) { return Int16(_mm512_or_si512(a.v, b.v)); }
inline Int16 operator>>(Int16 a, int n) { return Int16(_mm512_srai_epi32(a.v, static_cast<unsigned>(n))); }
inline Int16 operator<<(Int16 a, int n) { return Int16(_mm512_slli_epi32(a.v, static_cast<unsigned>(n))); }
inline Int16 select(Mask16 mask, Int16 a, Int16 b) { return Int16(_mm512_mask_blend_epi32(mask.m, b.v, a.v)); }
inline Int16 bitsOf(Float16 x) { return Int16(_mm512_castps_si512(x.v)); }
inline Float16 floatOfBits(Int16 i) { return Float16(_mm512_castsi512_ps(i.v)); }
inline Float16 toFloat(Int16 i) { return Float16(_mm512_cvtepi32_ps(i.v)); }
inline Int16 truncateToInt(Float16 x) { return Int16(_mm512_cvttps_epi32(x.v)); }
inline Mask16 equalLanes(Int16 a, Int16 b) { return {_mm512_cmpeq_epi32_mask(a.v, b.v)}; }
inline void storeLanes(std::int32_t* p, Int16 i) { _mm512_store_si512(p, i.v); }  // aligned to 64 bytes
inline Float16 floorOf(Float16 x) {  // as Float4's: truncate, then one less where that went up (so floor(-0) is +0 here too)
  const Float16 t = toFloat(truncateToInt(x));
  return select(x < t, t - Float16(1.0f), t);
}

struct Vec3x16 {
  Float16 x, y, z;
  Vec3x16() = default;
  Vec3x16(Float16 a, Float16 b, Float16 c) : x(a), y(b), z(c) {}
  explicit Vec3x16(glm::vec3 v) : x(v.x), y(v.y), z(v.z) {}
};
inline Vec3x16 operator+(const Vec3x16& a, const Vec3x16& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3x16 operator-(const Vec3x16& a, const Vec3x16& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3x16 operator-(const Vec3x16& a) { return {-a.x, -a.y, -a.z}; }
inline Vec3x16 operator*(Float16 s, const Vec3x16& v) { return {s * v.x, s * v.y, s * v.z}; }
inline Vec3x16 operator*(const Vec3x16& v, Float16 s) { return {v.x * s, v.y * s, v.z * s}; }
inline Vec3x16 operator*(const Vec3x16& a, const Vec3x16& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline Vec3x16 operator/(const Vec3x16& v, Float16 s) { return {v.x / s, v.y / s, v.z / s}; }
inline Vec3x16 select(Mask16 mask, const Vec3x16& a, const Vec3x16& b) {
  return {select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z)};
}
// Sixteen lanes from / to sixteen floats aligned to 64 bytes.
inline void loadLanes(Float16& x, const float* p) { x = Float16(_mm512_load_ps(p)); }
inline void storeLanes(float* p, Float16 x) { _mm512_store_ps(p, x.v); }
inline void loadLanesUnaligned(Float16& x, const float* p) { x = Float16(_mm512_loadu_ps(p)); }
inline void storeLanesUnaligned(float* p, Float16 x) { _mm512_storeu_ps(p, x.v); }

// The eight low lanes (half 0) or high lanes (half 1), for code written for eight lanes.
inline Float8 halfOf(Float16 a, int half) {
  return Float8(half == 0 ? _mm512_castps512_ps256(a.v) : _mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(a.v), 1)));
}
inline Mask8 halfOf(Mask16 a, int half) {
  const __m512i lanes = _mm512_maskz_set1_epi32(a.m, -1);  // all ones where the bit is set
  return {_mm256_castsi256_ps(half == 0 ? _mm512_castsi512_si256(lanes) : _mm512_extracti64x4_epi64(lanes, 1))};
}
inline Vec3x8 halfOf(const Vec3x16& a, int half) { return {halfOf(a.x, half), halfOf(a.y, half), halfOf(a.z, half)}; }
inline Float16 joined(Float8 low, Float8 high) {
  return Float16(_mm512_castpd_ps(_mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_castps_pd(low.v)), _mm256_castps_pd(high.v), 1)));
}
inline Vec3x16 joined(const Vec3x8& low, const Vec3x8& high) { return {joined(low.x, high.x), joined(low.y, high.y), joined(low.z, high.z)}; }
// unpacklo, unpackhi and shuffle on sixteen lanes, for transposeQuarters.
template <>
struct Shuffles<Float16> {
  static Float16 low(Float16 a, Float16 b) { return Float16(_mm512_unpacklo_ps(a.v, b.v)); }
  static Float16 high(Float16 a, Float16 b) { return Float16(_mm512_unpackhi_ps(a.v, b.v)); }
  template <int kPick>
  static Float16 pick(Float16 a, Float16 b) { return Float16(_mm512_shuffle_ps(a.v, b.v, kPick)); }
};
// loadPixels and storePixels on sixteen lanes: register k holds pixels k,
// k + 4, k + 8 and k + 12 in its four quarters, as Float8's does in its halves.
// Sixteen pixels side by side in the buffer (a run's, or runs' next to each
// other) are four 64-byte loads or stores instead, their quarters swapped
// into that order by swapQuarters.
inline bool sixteenInARow(const std::size_t* offsets, int count) {
  if (count < 16) return false;
  const __m512i first = _mm512_set1_epi64(static_cast<long long>(offsets[0]));
  const __m512i low = _mm512_add_epi64(first, _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7));
  const __m512i high = _mm512_add_epi64(low, _mm512_set1_epi64(8));
  return (_mm512_cmpeq_epi64_mask(_mm512_loadu_si512(offsets), low) & _mm512_cmpeq_epi64_mask(_mm512_loadu_si512(offsets + 8), high)) == 0xFF;
}
// Quarter j of register i to quarter i of register j (its own inverse).
inline void swapQuarters(Float16 (&p)[4]) {
  const __m512 t0 = _mm512_shuffle_f32x4(p[0].v, p[1].v, 0x44), t1 = _mm512_shuffle_f32x4(p[0].v, p[1].v, 0xEE);
  const __m512 t2 = _mm512_shuffle_f32x4(p[2].v, p[3].v, 0x44), t3 = _mm512_shuffle_f32x4(p[2].v, p[3].v, 0xEE);
  p[0] = Float16(_mm512_shuffle_f32x4(t0, t2, 0x88)), p[1] = Float16(_mm512_shuffle_f32x4(t0, t2, 0xDD));
  p[2] = Float16(_mm512_shuffle_f32x4(t1, t3, 0x88)), p[3] = Float16(_mm512_shuffle_f32x4(t1, t3, 0xDD));
}
inline void loadPixels(const float* rgba, const std::size_t* offsets, int count, Vec3x16& color, Float16& alpha) {
  Float16 pixel[4];
  if (sixteenInARow(offsets, count)) {
    for (int k = 0; k < 4; ++k) pixel[k] = Float16(_mm512_loadu_ps(rgba + 4 * offsets[0] + 16 * k));
    swapQuarters(pixel);
  } else {
    const auto at = [&](int k) { return k < count ? _mm_loadu_ps(rgba + 4 * offsets[k]) : _mm_setzero_ps(); };
    for (int k = 0; k < 4; ++k)
      pixel[k] = Float16(_mm512_insertf32x4(_mm512_insertf32x4(_mm512_insertf32x4(_mm512_castps128_ps512(at(k)), at(k + 4), 1), at(k + 8), 2), at(k + 12), 3));
  }
  transposeQuarters(pixel);
  color = {pixel[0], pixel[1], pixel[2]}, alpha = pixel[3];
}
inline void storePixels(float* rgba, const std::size_t* offsets, int count, const Vec3x16& color, Float16 alpha) {
  Float16 pixel[4] = {color.x, color.y, color.z, alpha};
  transposeQuarters(pixel);
  if (sixteenInARow(offsets, count)) {
    swapQuarters(pixel);
    for (int k = 0; k < 4; ++k) _mm512_storeu_ps(rgba + 4 * offsets[0] + 16 * k, pixel[k].v);
    return;
  }
  for (int k = 0; k < 4; ++k) {
    if (k < count) _mm_storeu_ps(rgba + 4 * offsets[k], _mm512_castps512_ps128(pixel[k].v));
    if (k + 4 < count) _mm_storeu_ps(rgba + 4 * offsets[k + 4], _mm512_extractf32x4_ps(pixel[k].v, 1));
    if (k + 8 < count) _mm_storeu_ps(rgba + 4 * offsets[k + 8], _mm512_extractf32x4_ps(pixel[k].v, 2));
    if (k + 12 < count) _mm_storeu_ps(rgba + 4 * offsets[k + 12], _mm512_extractf32x4_ps(pixel[k].v, 3));
  }
}

#endif

// The vector and integer types that go with a lane type.
template <class F>
struct LaneTypes;
template <>
struct LaneTypes<float> {
  using Vec3 = glm::vec3;
  using Int = std::int32_t;
  using Mask = bool;
};
#if defined(__SSE2__)
template <>
struct LaneTypes<Float4> {
  using Vec3 = Vec3x4;
  using Int = Int4;
  using Mask = Mask4;
};
#endif
#if defined(__AVX2__)
template <>
struct LaneTypes<Float8> {
  using Vec3 = Vec3x8;
  using Int = Int8;
  using Mask = Mask8;
};
#endif
#if defined(__AVX512F__)
template <>
struct LaneTypes<Float16> {
  using Vec3 = Vec3x16;
  using Int = Int16;
  using Mask = Mask16;
};
#endif
template <class F>
using Vec3Of = typename LaneTypes<F>::Vec3;
template <class F>
using IntOf = typename LaneTypes<F>::Int;
template <class F>
using MaskOf = typename LaneTypes<F>::Mask;

// How many lanes a lane type has (1 for float).
template <class F>
inline constexpr int kLaneCount = static_cast<int>(sizeof(F) / sizeof(float));

// A world-space vector as a lane type's vector (the same in every lane).
template <class F>
Vec3Of<F> splat(glm::vec3 v) {
  return Vec3Of<F>(v);
}

}  // namespace facet
