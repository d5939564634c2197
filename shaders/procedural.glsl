// Procedural textures (renderer/PIPELINE.md, "Textures"): a checker and four
// octaves of value noise of the model-space point.
// Mirror: renderer/shading/procedural.h — same functions, same order.

const int kProceduralChecker = 1;  // settings' Procedural::Checker (Noise is 2)

// floor(x) as an integer, clamped to ±2^24 first (as texel indices are).
int latticeIndex(float floored) {
  return int(floored < -16777216.0 ? -16777216.0 : (floored > 16777216.0 ? 16777216.0 : floored));
}

// The lattice value at integer corner (x, y, z), in [0, 1): uint arithmetic wraps modulo 2^32.
float latticeValue(int x, int y, int z) {
  uint h = (uint(x) * 73856093u) ^ (uint(y) * 19349663u) ^ (uint(z) * 83492791u);
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  precise float v = float(h >> 8) * (1.0 / 16777216.0);
  return v;
}

float mixScalar(float a, float b, float t) {
  precise float r = a + t * (b - a);
  return r;
}

// Value noise v(q) in [0, 1).
float valueNoise(vec3 q) {
  precise vec3 fl = floor(q);
  int x = latticeIndex(fl.x), y = latticeIndex(fl.y), z = latticeIndex(fl.z);
  precise vec3 t = q - fl;
  precise vec3 u = t * t * (3.0 - 2.0 * t);
  float x00 = mixScalar(latticeValue(x, y, z), latticeValue(x + 1, y, z), u.x);
  float x10 = mixScalar(latticeValue(x, y + 1, z), latticeValue(x + 1, y + 1, z), u.x);
  float x01 = mixScalar(latticeValue(x, y, z + 1), latticeValue(x + 1, y, z + 1), u.x);
  float x11 = mixScalar(latticeValue(x, y + 1, z + 1), latticeValue(x + 1, y + 1, z + 1), u.x);
  return mixScalar(mixScalar(x00, x10, u.y), mixScalar(x01, x11, u.y), u.z);
}

// The pattern's grey at model-space point P scaled by k.
float proceduralGrey(int pattern, vec3 P, float k) {
  precise vec3 p = P * k;
  if (pattern == kProceduralChecker) {
    precise vec3 fl = floor(p);
    int c = latticeIndex(fl.x) + latticeIndex(fl.y) + latticeIndex(fl.z);
    return (c & 1) == 0 ? 1.0 : 0.05;
  }
  precise float sum = ((valueNoise(p) + 0.5 * valueNoise(2.0 * p)) + 0.25 * valueNoise(4.0 * p)) + 0.125 * valueNoise(8.0 * p);
  precise float g = sum / 1.875;
  return g;
}
