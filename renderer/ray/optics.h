#pragma once
// The laws the recursive rays follow (renderer/PIPELINE.md, "Ray tracing",
// "Recursive ray tracing"): the law of reflection, Snell's law with total
// internal reflection, and Schlick's approximation of Fresnel's reflectance.
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "pipeline/microfacet.h"

namespace facet::ray {

// R = D - 2(D·N)N: D the unit incoming direction, N the unit normal.
inline glm::vec3 reflected(glm::vec3 D, glm::vec3 N) { return D - (2.0f * glm::dot(D, N)) * N; }

// What crosses from index n1 into n2: the unit direction T and cos θ2.
struct Refraction {
  glm::vec3 T{0.0f};
  float cosTransmitted = 1.0f;
};

// Snell's law, n1 sin θ1 = n2 sin θ2, for unit D and a unit N facing it
// (D·N < 0): T = η·D + (η·c1 - c2)·N, η = n1/n2, c1 = -D·N,
// c2 = sqrt(1 - η²(1 - c1²)). Nothing when 1 - η²(1 - c1²) < 0: total
// internal reflection, past the critical angle sin θ_c = n2/n1.
// An infinite n1 (KHR_materials_ior's ior 0) reflects every ray.
inline std::optional<Refraction> refracted(glm::vec3 D, glm::vec3 N, float n1, float n2) {
  if (std::isinf(n1)) return std::nullopt;
  const float eta = n1 / n2, c1 = -glm::dot(D, N);
  const float k = 1.0f - eta * eta * (1.0f - c1 * c1);
  if (k < 0.0f) return std::nullopt;
  const float c2 = std::sqrt(k);
  return Refraction{eta * D + (eta * c1 - c2) * N, c2};
}

// Schlick: F = F0 + (1 - F0)(1 - c)^5 (pipeline/microfacet.h), F0 =
// ((n1 - n2)/(n1 + n2))², c the cosine on the side of the smaller index (c1
// entering a denser medium, c2 leaving it).
// (1 - c)^5 is std::pow's, not shading=pbr's (x²·x²)·x, which its GLSL
// mirror fixes: the two round differently for one float c in seventeen of
// [0, 1] (63 million of them), so that form would change the ray tracer's images.
// An infinite index on either side (KHR_materials_ior's ior 0) gives F = 1 at every angle.
inline float fresnelSchlick(float n1, float n2, float cosIncident, float cosTransmitted) {
  if (std::isinf(n1) || std::isinf(n2)) return 1.0f;
  const float r0 = (n1 - n2) / (n1 + n2), F0 = r0 * r0;
  const float c = n1 <= n2 ? cosIncident : cosTransmitted;
  return schlickReflectance(F0, std::pow(1.0f - c, 5.0f));
}

}  // namespace facet::ray
