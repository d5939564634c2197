// Base colour texture lookup, by hand from integer texel reads so that no
// hardware filtering differs between backends (renderer/PIPELINE.md, section 8).
// Mirror: renderer/cpu/texture_sampling.cpp.
//
// The texture is GL_RGBA8UI, read through a usampler2D: the shader divides
// the bytes by 255 itself, as the CPU does. (llvmpipe converts a normalized
// GL_RGBA8 texel as c·fl(1/255), which differs from c/255 in the last bit
// for half of the byte values; tests/gl/test_textures.cpp holds both.)

// IEC 61966-2-1 inverse: sRGB-encoded texel to linear.
vec3 decodeSrgb(vec3 c) {
  return mix(pow((c + 0.055) / 1.055, vec3(2.4)), c / 12.92, lessThanEqual(c, vec3(0.04045)));
}

// Texel (x, y), bottom row first, decoded to linear.
vec3 texel(usampler2D image, int x, int y) {
  return decodeSrgb(vec3(texelFetch(image, ivec2(x, y), 0).rgb) / 255.0);
}

// REPEAT: i mod size in [0, size), whichever sign % gives a negative i.
int wrap(int i, int size) {
  return ((i % size) + size) % size;
}

// a + t·(b - a), written out: the CPU mirror does the same, since glm::mix
// computes a·(1 - t) + b·t, which rounds differently.
vec3 lerp(vec3 a, vec3 b, float t) {
  return a + t * (b - a);
}

// Bilinear, REPEAT, no mipmaps; t = 0 is the top of the glTF image, and
// facet uploads images bottom row first.
vec3 sampleBaseColor(usampler2D image, vec2 st) {
  ivec2 size = textureSize(image, 0);
  float x = st.x * float(size.x) - 0.5;
  float y = (1.0 - st.y) * float(size.y) - 0.5;
  if (isinf(x) || isnan(x) || isinf(y) || isnan(y)) return texel(image, 0, 0);
  float x0 = floor(x), y0 = floor(y);
  float fx = x - x0, fy = y - y0;
  // The CPU reduces x0 with fmod before converting; the same integers while |x0| < 2^31.
  int ix = int(x0), iy = int(y0);
  int ix0 = wrap(ix, size.x), ix1 = wrap(ix + 1, size.x), iy0 = wrap(iy, size.y), iy1 = wrap(iy + 1, size.y);
  vec3 c00 = texel(image, ix0, iy0), c10 = texel(image, ix1, iy0);
  vec3 c01 = texel(image, ix0, iy1), c11 = texel(image, ix1, iy1);
  return lerp(lerp(c00, c10, fx), lerp(c01, c11, fx), fy);
}
