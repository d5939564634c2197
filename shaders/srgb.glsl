// sRGB by the tables of renderer/image/srgb.h, which the OpenGL backend
// uploads once into this block (binding 1). A linear value's 8-bit level:
// clamp to [0, 1] (NaN to 0), the bucket of its bits >> 15 gives the level
// of the bucket's first float, plus one when the next threshold is at or
// below the value. An 8-bit texel's linear value is read. Mirror:
// facet::encodeLevel and SrgbTables::decoded, the same tables and steps, so
// both backends write the same bytes.
layout(std140, binding = 1) uniform SrgbTables {
  vec4 thresholds[65];  // [k / 4][k % 4]: the smallest linear value of level k (k = 1..255); [256]: +inf
  vec4 decoded[64];     // [v / 4][v % 4]: the linear value of 8-bit level v
  uvec4 buckets[2033];  // byte b (16 to a uvec4, 4 to a uint, lowest first): the level at the start of bucket b
} srgb;

int encodeLevel(float linear) {
  float c = linear > 0.0 ? (linear < 1.0 ? linear : 1.0) : 0.0;
  uint bucket = floatBitsToUint(c) >> 15u;
  uint word = srgb.buckets[bucket >> 4u][(bucket >> 2u) & 3u];
  int start = int((word >> ((bucket & 3u) * 8u)) & 0xFFu);
  int next = start + 1;
  return srgb.thresholds[next >> 2][next & 3] <= c ? next : start;
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
