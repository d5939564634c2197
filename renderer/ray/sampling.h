#pragma once
// Stochastic ray tracing's random numbers (renderer/PIPELINE.md, "Ray tracing",
// "Stochastic ray tracing"): one generator per path, seeded by the frame's
// seed, the pixel and the path's index, so that an image depends on the seed
// alone, not on the threads or the order of the tiles; and the shapes the
// paths sample: the pixel, the lens's disk, a light's disk or cone, a Phong lobe.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "common/random.h"

namespace facet::ray {

// One path's numbers: common/random.h's SplitMix64, started from the seed,
// the pixel and the path.
class PathSampler {
 public:
  PathSampler(std::uint32_t seed, std::uint32_t pixel, std::uint32_t path)
      : random_((std::uint64_t{seed} << 40) ^ (std::uint64_t{pixel} << 12) ^ std::uint64_t{path} ^ 0x5851F42D4C957F2Dull) {
    random_.next();  // one step so that neighbouring seeds do not start alike
  }
  float uniform() { return random_.unitFloat(); }  // in [0, 1): k/2^24
  glm::vec2 uniform2() {
    const float u = uniform();
    return {u, uniform()};
  }

 private:
  SplitMix64 random_;
};

// Path k of n's offset from the pixel centre, in [-0.5, 0.5)²: stratified on
// an s × s grid where n = s² (one jittered position per cell, row by row),
// uniform over the pixel otherwise.
inline glm::vec2 pixelJitter(int k, int n, glm::vec2 u) {
  int s = 1;
  while ((s + 1) * (s + 1) <= n) ++s;
  if (s * s != n) return u - 0.5f;
  return {(static_cast<float>(k % s) + u.x) / static_cast<float>(s) - 0.5f, (static_cast<float>(k / s) + u.y) / static_cast<float>(s) - 0.5f};
}

// A point of the unit disk, uniform by area: r = sqrt(u), φ = 2πv.
inline glm::vec2 diskPoint(glm::vec2 u) {
  const float r = std::sqrt(u.x), phi = 2.0f * std::numbers::pi_v<float> * u.y;
  return {r * std::cos(phi), r * std::sin(phi)};
}

// Two unit vectors completing w (unit) to an orthonormal frame (Duff et al. 2017).
inline void frameAround(glm::vec3 w, glm::vec3& a, glm::vec3& b) {
  const float sign = std::copysign(1.0f, w.z);
  const float p = -1.0f / (sign + w.z), q = w.x * w.y * p;
  a = {1.0f + sign * w.x * w.x * p, sign * q, -sign * w.x};
  b = {q, sign + w.y * w.y * p, -w.y};
}

// A direction about unit `axis` with density ∝ cos^n of the angle to it
// (the course's Phong lobe): cos θ = u^(1/(n+1)), φ = 2πv. With n = 0 and
// cosMax in place of the lobe (`uniformCone`), uniform in the cone of cos θ ≥ cosMax.
inline glm::vec3 aroundAxis(glm::vec3 axis, float cosTheta, float phi) {
  glm::vec3 a, b;
  frameAround(axis, a, b);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  return (sinTheta * std::cos(phi)) * a + (sinTheta * std::sin(phi)) * b + cosTheta * axis;
}
inline glm::vec3 phongLobe(glm::vec3 axis, float n, glm::vec2 u) {
  return aroundAxis(axis, std::pow(u.x, 1.0f / (n + 1.0f)), 2.0f * std::numbers::pi_v<float> * u.y);
}
inline glm::vec3 uniformCone(glm::vec3 axis, float cosMax, glm::vec2 u) {
  return aroundAxis(axis, 1.0f - u.x * (1.0f - cosMax), 2.0f * std::numbers::pi_v<float> * u.y);
}

}  // namespace facet::ray
