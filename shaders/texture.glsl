// Base colour texture lookup, by hand from integer texel reads so that no
// hardware filtering differs between backends (renderer/PIPELINE.md, section 8).
// Mirror: renderer/cpu/texture_sampling.cpp. Needs srgb.glsl before it.
//
// The texture is GL_RGBA8UI, read through a usampler2D: bytes, decoded to
// linear by the shared table (srgb.glsl), as the CPU does.

// Texel (x, y), bottom row first, decoded to linear.
vec3 texel(usampler2D image, int x, int y) {
  uvec3 c = texelFetch(image, ivec2(x, y), 0).rgb;
  return vec3(decodeSrgb(c.r), decodeSrgb(c.g), decodeSrgb(c.b));
}

// REPEAT: i mod size in [0, size), with % only on non-negative operands
// (GLSL leaves % on negatives undefined; llvmpipe divides the bit patterns unsigned).
int wrap(int i, int size) {
  return i >= 0 ? i % size : size - 1 - (-1 - i) % size;
}

// floor(x) as a texel index: beyond ±2^24 every float is a whole number, and
// the clamp keeps the conversion defined without changing any texel inside.
int texelIndex(float x0) {
  return int(x0 < -16777216.0 ? -16777216.0 : (x0 > 16777216.0 ? 16777216.0 : x0));
}

// a + t·(b - a), written out: `precise` keeps the compiler from turning it into mix.
vec3 lerp(vec3 a, vec3 b, float t) {
  precise vec3 r = a + t * (b - a);
  return r;
}

// Bilinear, REPEAT, no mipmaps; t = 0 is the top of the glTF image, and
// facet uploads images bottom row first.
vec3 sampleBaseColor(usampler2D image, vec2 st) {
  ivec2 size = textureSize(image, 0);
  precise float x = st.x * float(size.x) - 0.5;
  precise float y = (1.0 - st.y) * float(size.y) - 0.5;
  if (isinf(x) || isnan(x) || isinf(y) || isnan(y)) return texel(image, 0, 0);
  precise float x0 = floor(x), y0 = floor(y);
  precise float fx = x - x0, fy = y - y0;
  int ix = texelIndex(x0), iy = texelIndex(y0);
  int ix0 = wrap(ix, size.x), ix1 = wrap(ix + 1, size.x), iy0 = wrap(iy, size.y), iy1 = wrap(iy + 1, size.y);
  vec3 c00 = texel(image, ix0, iy0), c10 = texel(image, ix1, iy0);
  vec3 c01 = texel(image, ix0, iy1), c11 = texel(image, ix1, iy1);
  return lerp(lerp(c00, c10, fx), lerp(c01, c11, fx), fy);
}
