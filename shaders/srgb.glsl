// sRGB by the tables of renderer/image/srgb.h, which the OpenGL backend
// uploads once into this block (binding 1): a linear value's 8-bit level is
// the number of the 255 thresholds at or below it, found by binary search;
// an 8-bit texel's linear value is read. Mirror: facet::encodeLevel and
// SrgbTables::decoded, the same tables, so both backends write the same bytes.
layout(std140, binding = 1) uniform SrgbTables {
  vec4 thresholds[64];  // [k / 4][k % 4]: the smallest linear value of level k (k = 1..255)
  vec4 decoded[64];     // [v / 4][v % 4]: the linear value of 8-bit level v
} srgb;

float srgbThreshold(int k) {
  return srgb.thresholds[k >> 2][k & 3];
}

// 0..255 for any float: NaN and below 0 give 0, above 1 gives 255.
int encodeLevel(float linear) {
  int level = 0;
  for (int step = 128; step > 0; step >>= 1)
    if (srgbThreshold(level + step) <= linear) level += step;
  return level;
}

// The colour to write into the RGBA8 target: each level / 255, which the
// driver converts back to exactly that level.
vec4 encodeSrgb(vec3 linear) {
  return vec4(float(encodeLevel(linear.r)) / 255.0, float(encodeLevel(linear.g)) / 255.0, float(encodeLevel(linear.b)) / 255.0, 1.0);
}

float decodeSrgb(uint level) {
  return srgb.decoded[level >> 2u][level & 3u];
}
