// sRGB by the tables of renderer/image/srgb.h, which the OpenGL backend
// uploads once into this block (binding 1). A linear value's 8-bit level:
// clamp to [0, 1] (NaN to 0), then raise to 2^-13 (whose level 0 every
// smaller value shares); the entry of its bucket (bits >> 15, from 2^-13's
// bucket on) holds the level of the bucket's first float above bit 15 and
// 2^15 minus where in the bucket the next level begins below it, so adding
// the value's low 15 bits carries into the level where they reach that
// edge: the level is (entry + (bits & 0x7FFF)) >> 15. An 8-bit texel's
// linear value is read. Mirror: facet::encodeLevel and SrgbTables::decoded,
// the same tables and steps, so both backends write the same bytes.
layout(std140, binding = 1) uniform SrgbTables {
  vec4 decoded[64];     // [v / 4][v % 4]: the linear value of 8-bit level v
  uvec4 buckets[833];   // [b / 4][b % 4]: the entry of the b-th bucket from 2^-13's, start << 15 | (2^15 - edge)
} srgb;

const float kSrgbFloor = 1.0 / 8192.0;  // 2^-13, below level 1
const uint kSrgbFirstBucket = floatBitsToUint(kSrgbFloor) >> 15u;

int encodeLevel(float linear) {
  float c = max(linear > 0.0 ? (linear < 1.0 ? linear : 1.0) : 0.0, kSrgbFloor);
  uint bits = floatBitsToUint(c);
  uint b = (bits >> 15u) - kSrgbFirstBucket;
  uint entry = srgb.buckets[b >> 2u][b & 3u];
  return int((entry + (bits & 0x7FFFu)) >> 15u);
}

// Alpha is coverage, not light: floor(255·a + 0.5) of a clamped to [0, 1]
// (NaN to 0), a product and a sum each rounded once. Mirror: facet::alphaLevel.
int alphaLevel(float alpha) {
  float c = alpha > 0.0 ? (alpha < 1.0 ? alpha : 1.0) : 0.0;
  precise float scaled = c * 255.0 + 0.5;  // never fused into one rounding
  return int(scaled);
}

// The resolve's colour for the RGBA8 target: each level / 255, which the
// driver converts back to exactly that level.
vec4 encodeSrgb(vec4 linear) {
  return vec4(float(encodeLevel(linear.r)) / 255.0, float(encodeLevel(linear.g)) / 255.0, float(encodeLevel(linear.b)) / 255.0,
              float(alphaLevel(linear.a)) / 255.0);
}

float decodeSrgb(uint level) {
  return srgb.decoded[level >> 2u][level & 3u];
}
