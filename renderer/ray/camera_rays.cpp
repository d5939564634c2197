#include "ray/camera_rays.h"

#include <cmath>

#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

namespace facet::ray {

Ray primaryRay(const FrameInputs& frame, int px, int py, glm::vec2 offset) {
  const double width = frame.width, height = frame.height;
  const double i = px + static_cast<double>(offset.x), j = (frame.height - 1 - py) - static_cast<double>(offset.y);
  // EM = Mirror_x·GRM·T(-P_eye): its 3x3 part is orthogonal, so its inverse is its transpose.
  const glm::dmat3 worldFromEye = glm::transpose(glm::dmat3(glm::mat3(frame.eyeFromWorld)));
  Ray ray;
  ray.tMin = frame.camera.near;
  ray.tMax = frame.camera.far;
  if (frame.perspective) {
    const double tanTheta = std::tan(glm::radians(static_cast<double>(frame.camera.halfAngleDeg)));
    const double aspect = width / height;  // A_R
    const double x = -tanTheta + 2.0 * (i + 0.5) * tanTheta / width;
    const double y = (tanTheta - (j + 0.5) * 2.0 * tanTheta / height) / aspect;
    ray.origin = frame.eyePosition;
    ray.direction = glm::vec3(worldFromEye * glm::dvec3(x, y, 1.0));
    return ray;
  }
  // Parallel: the pixel centre in NDC, scaled to the box of width W and height H = W/A_R.
  const double w = frame.camera.parallelWidth, h = w * height / width;
  const double x = (2.0 * (i + 0.5) / width - 1.0) * 0.5 * w;
  const double y = (1.0 - 2.0 * (j + 0.5) / height) * 0.5 * h;
  ray.origin = glm::vec3(glm::dvec3(frame.eyePosition) + worldFromEye * glm::dvec3(x, y, 0.0));
  ray.direction = glm::vec3(worldFromEye * glm::dvec3(0.0, 0.0, 1.0));
  return ray;
}

Ray centreRay(const FrameInputs& frame) {
  return primaryRay(frame, frame.width / 2, frame.height / 2,
                    glm::vec2(frame.width % 2 == 0 ? -0.5f : 0.0f, frame.height % 2 == 0 ? -0.5f : 0.0f));
}

Ray throughLens(const FrameInputs& frame, const Ray& pinhole, glm::vec2 disk, float f) {
  if (!(frame.camera.aperture > 0.0f) || !(f > 0.0f)) return pinhole;
  const glm::mat3 worldFromEye = glm::transpose(glm::mat3(frame.eyeFromWorld));
  const glm::vec3 focus = pinhole.origin + f * pinhole.direction;
  Ray ray = pinhole;
  ray.origin = pinhole.origin + frame.camera.aperture * (disk.x * worldFromEye[0] + disk.y * worldFromEye[1]);
  ray.direction = (focus - ray.origin) / f;
  return ray;
}

}  // namespace facet::ray
