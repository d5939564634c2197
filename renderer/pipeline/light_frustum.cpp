#include "pipeline/light_frustum.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "math/eye_matrix.h"
#include "math/projection.h"

namespace facet {
namespace {

glm::vec3 upFor(glm::vec3 forward) {
  return std::fabs(forward.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
}

}  // namespace

int cubeFace(glm::vec3 d) {
  const glm::vec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
  return d.z >= 0.0f ? 4 : 5;
}

LightFrustum lightFrustum(const Light& light, const Sphere& scene) {
  LightFrustum f;
  const float margin = 1.05f * scene.radius;
  // A light inside (or at the edge of) the sphere would get near ≈ 0, and a
  // perspective map's depth z' = A + B/z would then spend all its precision
  // next to the light: with near = far/1000 a bias of 0.001 spans metres.
  // Geometry closer to the light than this floor casts no shadow.
  const float nearFloor = 0.05f * scene.radius;
  switch (light.kind) {
    case LightKind::Directional: {
      // Parallel projection of a box around the sphere, from 2r back along the light.
      const glm::vec3 d = glm::normalize(light.direction);
      const glm::vec3 eye = scene.center - 2.0f * scene.radius * d;
      f.near = 2.0f * scene.radius - margin;
      f.far = 2.0f * scene.radius + margin;
      f.faceCount = 1;
      f.clipFromWorld[0] = parallel(2.0f * margin, 2.0f * margin, f.near, f.far) * eyeMatrix(eye, scene.center, upFor(d));
      break;
    }
    case LightKind::Spot: {
      // The cone is the angle of view: θ = β on a square map.
      const glm::vec3 d = glm::normalize(light.direction);
      const float along = glm::dot(scene.center - light.position, d);
      f.far = std::max(along + margin, 2.0f * nearFloor);
      f.near = std::max(along - margin, nearFloor);
      f.faceCount = 1;
      f.clipFromWorld[0] = perspective(glm::radians(light.spotCutoffDeg), 1.0f, f.near, f.far) *
                           eyeMatrix(light.position, pointAlong(light.position, d), upFor(d));
      break;
    }
    case LightKind::Point:
    case LightKind::Count: {
      // Six 90° views. A point in a face's frustum has z >= |P - P_light| / √3.
      const float distance = glm::length(scene.center - light.position);
      f.far = std::max(distance + margin, 2.0f * nearFloor);
      f.near = std::max((distance - margin) / std::numbers::sqrt3_v<float>, nearFloor);
      static const glm::vec3 kAxes[kCubeFaceCount] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      const glm::mat4 projection = perspective(std::numbers::pi_v<float> / 4.0f, 1.0f, f.near, f.far);
      f.faceCount = kCubeFaceCount;
      for (int face = 0; face < kCubeFaceCount; ++face)
        f.clipFromWorld[static_cast<std::size_t>(face)] =
            projection * eyeMatrix(light.position, pointAlong(light.position, kAxes[face]), upFor(kAxes[face]));
      break;
    }
  }
  return f;
}

}  // namespace facet
