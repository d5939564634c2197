#include "ray/camera_rays.h"

#include <cmath>

#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

namespace facet::ray {

CameraRays::CameraRays(const FrameInputs& frame)
    // EM = Mirror_x·GRM·T(-P_eye): its 3x3 part is orthogonal, so its inverse is its transpose.
    : worldFromEye_(glm::transpose(glm::dmat3(glm::mat3(frame.eyeFromWorld)))),
      eye_(frame.eyePosition),
      width_(frame.width),
      height_(frame.height),
      tanTheta_(std::tan(glm::radians(static_cast<double>(frame.camera.halfAngleDeg)))),
      aspect_(width_ / height_),  // A_R
      boxWidth_(frame.camera.parallelWidth),
      boxHeight_(boxWidth_ * height_ / width_),
      rows_(frame.height),
      near_(frame.camera.near),
      far_(frame.camera.far),
      perspective_(frame.perspective) {}

Ray CameraRays::at(int px, int py, glm::vec2 offset) const {
  const double i = px + static_cast<double>(offset.x), j = (rows_ - 1 - py) - static_cast<double>(offset.y);
  Ray ray;
  ray.tMin = near_;
  ray.tMax = far_;
  if (perspective_) {
    const double x = -tanTheta_ + 2.0 * (i + 0.5) * tanTheta_ / width_;
    const double y = (tanTheta_ - (j + 0.5) * 2.0 * tanTheta_ / height_) / aspect_;
    ray.origin = glm::vec3(eye_);
    ray.direction = glm::vec3(worldFromEye_ * glm::dvec3(x, y, 1.0));
    return ray;
  }
  // Parallel: the pixel centre in NDC, scaled to the box of width W and height H = W/A_R.
  const double x = (2.0 * (i + 0.5) / width_ - 1.0) * 0.5 * boxWidth_;
  const double y = (1.0 - 2.0 * (j + 0.5) / height_) * 0.5 * boxHeight_;
  ray.origin = glm::vec3(eye_ + worldFromEye_ * glm::dvec3(x, y, 0.0));
  ray.direction = glm::vec3(worldFromEye_ * glm::dvec3(0.0, 0.0, 1.0));
  return ray;
}

Ray primaryRay(const FrameInputs& frame, int px, int py, glm::vec2 offset) { return CameraRays(frame).at(px, py, offset); }

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
