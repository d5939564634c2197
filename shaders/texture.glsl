// Texture lookup by hand from integer texel reads, so that no hardware
// filtering differs between backends: level of detail, the sampler's filters
// and wraps (renderer/PIPELINE.md, "Textures").
// Mirror: renderer/shading/texture.cpp. Needs shading_math.glsl and srgb.glsl before it.
//
// The texture is GL_RGBA8UI with the loader's mipmaps as its levels, read
// through a usampler2D: bytes, decoded to linear by the shared table
// (srgb.glsl), as the CPU does.

// scene/scene.h's MagFilter, MinFilter and Wrap, as the sampler uniform carries them.
const int kFilterLinear = 1;                 // MagFilter::Linear
const int kMinNearest = 0, kMinLinear = 1;   // MinFilter: no mipmaps
const int kMinNearestMipmapNearest = 2, kMinLinearMipmapNearest = 3, kMinLinearMipmapLinear = 5;
const int kWrapClampToEdge = 1, kWrapMirroredRepeat = 2;

// Texel (x, y) of a level, bottom row first: colour decoded to linear (srgb),
// or data read as byte / 255; alpha as stored.
vec4 texel(usampler2D image, int level, int x, int y, bool srgb) {
  uvec4 c = texelFetch(image, ivec2(x, y), level);
  precise vec4 data = vec4(c) / 255.0;
  return srgb ? vec4(decodeSrgb(c.r), decodeSrgb(c.g), decodeSrgb(c.b), data.a) : data;
}

// REPEAT: i mod size in [0, size), with % only on non-negative operands
// (GLSL leaves % on negatives undefined; llvmpipe divides the bit patterns unsigned).
int wrap(int i, int size) {
  return i >= 0 ? i % size : size - 1 - (-1 - i) % size;
}

// The texel index i on an axis of `size` texels under wrap `mode`.
int wrapIndex(int i, int size, int mode) {
  if (mode == kWrapClampToEdge) return min(max(i, 0), size - 1);
  if (mode == kWrapMirroredRepeat) {
    int m = wrap(i, 2 * size);
    return m < size ? m : 2 * size - 1 - m;
  }
  return wrap(i, size);
}

// floor(x) as a texel index: beyond ±2^24 every float is a whole number, and
// the clamp keeps the conversion defined without changing any texel inside.
int texelIndex(float x0) {
  return int(x0 < -16777216.0 ? -16777216.0 : (x0 > 16777216.0 ? 16777216.0 : x0));
}

// a + t·(b - a), written out: `precise` keeps the compiler from turning it into mix.
vec4 lerp(vec4 a, vec4 b, float t) {
  precise vec4 r = a + t * (b - a);
  return r;
}

// sampleLevel over the size.x × size.y texels from `origin` of a level, as
// if they were an image of their own (a face of an environment cube strip).
vec4 sampleRegion(usampler2D image, bool srgb, int level, ivec2 origin, ivec2 size, bool linear, int wrapS, int wrapT, vec2 st) {
  precise float u = st.x * float(size.x);
  precise float v = (1.0 - st.y) * float(size.y);
  if (!linear) {
    if (isinf(u) || isnan(u) || isinf(v) || isnan(v)) return texel(image, level, origin.x, origin.y, srgb);
    return texel(image, level, origin.x + wrapIndex(texelIndex(floor(u)), size.x, wrapS), origin.y + wrapIndex(texelIndex(floor(v)), size.y, wrapT), srgb);
  }
  precise float x = u - 0.5, y = v - 0.5;
  if (isinf(x) || isnan(x) || isinf(y) || isnan(y)) return texel(image, level, origin.x, origin.y, srgb);
  precise float x0 = floor(x), y0 = floor(y);
  precise float fx = x - x0, fy = y - y0;
  int ix = texelIndex(x0), iy = texelIndex(y0);
  int ix0 = origin.x + wrapIndex(ix, size.x, wrapS), ix1 = origin.x + wrapIndex(ix + 1, size.x, wrapS);
  int iy0 = origin.y + wrapIndex(iy, size.y, wrapT), iy1 = origin.y + wrapIndex(iy + 1, size.y, wrapT);
  vec4 c00 = texel(image, level, ix0, iy0, srgb), c10 = texel(image, level, ix1, iy0, srgb);
  vec4 c01 = texel(image, level, ix0, iy1, srgb), c11 = texel(image, level, ix1, iy1, srgb);
  return lerp(lerp(c00, c10, fx), lerp(c01, c11, fx), fy);
}

// One level, NEAREST or LINEAR: linear RGB and alpha; t = 0 is the top of
// the glTF image, and facet uploads images bottom row first. The size of a
// level is level 0's halved, as image/mipmap.h builds them: llvmpipe's
// textureSize reads one lane's level for all, and `level` varies between
// the pixels shaded together.
vec4 sampleLevel(usampler2D image, bool srgb, int level, bool linear, int wrapS, int wrapT, vec2 st) {
  ivec2 size0 = textureSize(image, 0);
  ivec2 size = ivec2(max(1, size0.x >> level), max(1, size0.y >> level));
  return sampleRegion(image, srgb, level, ivec2(0, 0), size, linear, wrapS, wrapT, st);
}

// ρ² from derivatives (ds/dx, dt/dx, ds/dy, dt/dy) and level 0's size.
float footprintSquared(vec4 d, ivec2 size) {
  precise float W = float(size.x), H = float(size.y);
  precise float a = d.x * W, b = d.y * H, c = d.z * W, e = d.w * H;
  precise float alongX = a * a + b * b, alongY = c * c + e * e;
  return alongX > alongY ? alongX : alongY;
}

// The texture through `sampler` (magFilter, minFilter, wrapS, wrapT) at st.
vec4 sampleTexture(usampler2D image, bool srgb, ivec4 sampler, vec2 st, vec4 derivatives) {
  ivec2 size = textureSize(image, 0);
  float rho2 = footprintSquared(derivatives, size);
  if (!(rho2 > 1.0)) return sampleLevel(image, srgb, 0, sampler.x == kFilterLinear, sampler.z, sampler.w, st);
  int minFilter = sampler.y;
  bool linear = minFilter == kMinLinear || minFilter == kMinLinearMipmapNearest || minFilter == kMinLinearMipmapLinear;
  if (minFilter == kMinNearest || minFilter == kMinLinear) return sampleLevel(image, srgb, 0, linear, sampler.z, sampler.w, st);
  precise float halfLog = 0.5 * log2Of(rho2);
  float lambda = halfLog > 0.0 ? halfLog : 0.0;
  int last = textureQueryLevels(image) - 1;
  if (minFilter == kMinNearestMipmapNearest || minFilter == kMinLinearMipmapNearest) {
    precise float nearest = floor(lambda + 0.5);
    int k = nearest < float(last) ? int(nearest) : last;
    return sampleLevel(image, srgb, k, linear, sampler.z, sampler.w, st);
  }
  precise float whole = floor(lambda);
  int k = whole < float(last) ? int(whole) : last;
  vec4 above = sampleLevel(image, srgb, k, linear, sampler.z, sampler.w, st);
  if (k == last) return above;
  vec4 below = sampleLevel(image, srgb, k + 1, linear, sampler.z, sampler.w, st);
  precise float f = lambda - whole;
  return lerp(above, below, f);
}
