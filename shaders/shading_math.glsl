// The few functions the shading code builds on, in the float operations of
// renderer/PIPELINE.md ("Arithmetic"). Mirror:
// renderer/shading/shading_math.h, the same names, the same operations in the
// same order. Only +, -, *, /, sqrt, floor, comparisons, selects and bit
// casts, each exact in llvmpipe as in C++; every result is `precise` so that
// the compiler keeps the order written (no rebalancing, factoring or
// folding). GLSL's dot, length and normalize are not used: llvmpipe sums a
// dot product from z to x.

// (a.x*b.x + a.y*b.y) + a.z*b.z
float dot3(vec3 a, vec3 b) {
  precise float r = (a.x * b.x + a.y * b.y) + a.z * b.z;
  return r;
}

// (a.y*b.z - a.z*b.y, a.z*b.x - a.x*b.z, a.x*b.y - a.y*b.x)
vec3 cross3(vec3 a, vec3 b) {
  precise vec3 r = vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  return r;
}

// sqrt(v.v)
float length3(vec3 v) {
  precise float r = sqrt(dot3(v, v));
  return r;
}

// v * (1 / sqrt(v.v))
vec3 normalize3(vec3 v) {
  precise float s = 1.0 / sqrt(dot3(v, v));
  precise vec3 r = vec3(v.x * s, v.y * s, v.z * s);
  return r;
}

// x > 0 ? x : 0, so NaN gives 0.
float maxZero(float x) {
  return x > 0.0 ? x : 0.0;
}

// x < 1 ? x : 1, so NaN gives 1.
float minOne(float x) {
  return x < 1.0 ? x : 1.0;
}

// x^y for the specular term: exp2(y*log2(x)) by the series of
// renderer/shading/shading_math.h (the comment there says how and how well).
const float kLog2Series[5] = float[5](2.88539004, 0.961796701, 0.577078044, 0.412198573, 0.3205989);
const float kExp2Series[10] = float[10](1.0, 0.693147182, 0.240226507, 0.0555041097, 0.00961812865, 0.00133335579, 0.000154035297,
                                        1.52527336e-05, 1.32154867e-06, 1.01780863e-07);
const float kSqrtTwo = 1.41421354;

// log2(x) for x > 0 by the series above (x ≤ 0 or NaN: not defined here; power guards it).
float log2Of(float x) {
  int bits = floatBitsToInt(x);
  precise float mantissa = intBitsToFloat((bits & 0x007FFFFF) | 0x3F800000);
  bool above = mantissa > kSqrtTwo;
  precise float m = above ? mantissa * 0.5 : mantissa;
  int e = above ? (bits >> 23) - 126 : (bits >> 23) - 127;
  precise float s = (m - 1.0) / (m + 1.0);
  precise float s2 = s * s;
  precise float series = kLog2Series[4];
  for (int k = 3; k >= 0; --k) series = kLog2Series[k] + s2 * series;
  precise float log2x = float(e) + s * series;
  return log2x;
}

// 2^t by the series above: t below -126 (or NaN) gives 0, above 127 is taken as 127.
float exp2Of(float t) {
  bool inRange = t >= -126.0;  // false for NaN
  precise float clamped = t > 127.0 ? 127.0 : (inRange ? t : 0.0);
  precise float whole = floor(clamped);
  precise float f = clamped - whole;
  precise float exp2f = kExp2Series[9];
  for (int k = 8; k >= 0; --k) exp2f = kExp2Series[k] + f * exp2f;
  precise float scale = intBitsToFloat((int(whole) + 127) << 23);
  precise float r = inRange ? exp2f * scale : 0.0;
  return r;
}

float power(float x, float y) {
  bool positive = x > 0.0;
  precise float log2x = log2Of(positive ? x : 1.0);
  precise float product = y * log2x;
  precise float r = positive ? exp2Of(product) : 0.0;
  return r;
}

// Face of a cube (a point light's for P - P_light, an environment map's for a direction): largest |component|, ties to x, then y, then z.
int cubeFace(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}
