#pragma once
// The light's eye and projection matrices for pass 1 of the course's 2-pass
// shadow algorithm, built with the same eyeMatrix / perspective / parallel as
// the camera, near and far fitted to the scene's bounding sphere.
#include <array>

#include <glm/mat4x4.hpp>

#include "pipeline/view_setup.h"
#include "vocabulary/light.h"

namespace facet {

struct LightFrustum {
  int faceCount = 0;                         // 1 (spot, directional) or 6 (point)
  std::array<glm::mat4, 6> clipFromWorld{};  // PM·EM of each face
  float near = 0, far = 0;                   // eye-space planes of every face
};

// Cube faces of a point light, in this order (also the GL array layers):
// +x, -x, +y, -y, +z, -z. A point P is read from the face of the axis where
// P - P_light has its largest absolute component, ties to x, then y, then z.
inline constexpr int kCubeFaceCount = 6;

LightFrustum lightFrustum(const Light& light, const Sphere& scene);

// Face index (0..5, order above) for the vector P - P_light.
int cubeFace(glm::vec3 fromLight);

}  // namespace facet
