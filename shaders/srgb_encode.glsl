// The sRGB encoding of a linear colour before it is written as 8 bits.
// Mirror: encodeSrgb in renderer/cpu/lighting.h (the background and every
// lit pixel go through it).

// Clamp to [0,1], then IEC 61966-2-1.
vec3 encodeSrgb(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  return mix(1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, 12.92 * c, lessThanEqual(c, vec3(0.0031308)));
}
