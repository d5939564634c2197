#include "viewer/camera_controls.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

namespace facet::viewer {
namespace {

constexpr float kZoomStep = 0.9f;        // what one wheel step keeps of the distance or width
constexpr float kPoleMarginDeg = 1.0f;   // how close to v_up an orbit may bring the line of sight

bool isUsable(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && glm::length(v) > 0.0f; }

// Distance from the eye to the sphere's centre, along the line of sight.
float depthOf(const CameraSettings& camera, glm::vec3 point) {
  const glm::vec3 sight = camera.reference - camera.eye;
  return isUsable(sight) ? glm::dot(point - camera.eye, glm::normalize(sight)) : 0.0f;
}

}  // namespace

void orbit(CameraSettings& camera, glm::vec2 pixels, float windowHeight) {
  glm::vec3 offset = camera.eye - camera.reference;
  if (!isUsable(offset) || !isUsable(camera.up)) return;
  const glm::vec3 up = glm::normalize(camera.up);
  const float radiansPerPixel = glm::pi<float>() / std::max(windowHeight, 1.0f);

  // Turntable: about v_up, the cursor dragging the scene along with it.
  offset = glm::angleAxis(-pixels.x * radiansPerPixel, up) * offset;

  // Over the top: the polar angle from v_up, dragging down looks from higher up.
  const float radius = glm::length(offset);
  const float polar = std::acos(std::clamp(glm::dot(offset / radius, up), -1.0f, 1.0f));
  const float margin = glm::radians(kPoleMarginDeg);
  const float target = std::clamp(polar - pixels.y * radiansPerPixel, margin, glm::pi<float>() - margin);
  const glm::vec3 axis = glm::cross(up, offset);  // horizontal, at right angles to the line of sight
  if (isUsable(axis)) offset = glm::angleAxis(target - polar, glm::normalize(axis)) * offset;
  camera.eye = camera.reference + offset;
}

void pan(CameraSettings& camera, glm::vec2 pixels, float windowWidth) {
  const glm::vec3 sight = camera.reference - camera.eye;
  const glm::vec3 side = glm::cross(sight, camera.up);
  if (!isUsable(sight) || !isUsable(side)) return;
  const glm::vec3 forward = glm::normalize(sight);
  const glm::vec3 right = glm::normalize(side);
  const glm::vec3 screenUp = glm::cross(right, forward);
  // World width of the view at P_ref: θ is the horizontal half-angle.
  const float viewWidth = camera.projection == ProjectionKind::Perspective
                              ? 2.0f * glm::length(sight) * std::tan(glm::radians(camera.halfAngleDeg))
                              : camera.parallelWidth;
  const float worldPerPixel = viewWidth / std::max(windowWidth, 1.0f);
  const glm::vec3 move = (-pixels.x * right + pixels.y * screenUp) * worldPerPixel;  // window y grows downward
  camera.eye += move;
  camera.reference += move;
}

void zoom(CameraSettings& camera, float steps, float minDistance) {
  const float factor = std::pow(kZoomStep, steps);
  if (camera.projection == ProjectionKind::Parallel) {
    camera.parallelWidth = std::clamp(camera.parallelWidth * factor, 1e-6f, 1e9f);  // the field table's range
    return;
  }
  const glm::vec3 offset = camera.eye - camera.reference;
  if (!isUsable(offset)) return;
  const float distance = std::max(glm::length(offset) * factor, minDistance);
  camera.eye = camera.reference + glm::normalize(offset) * distance;
}

void toggleProjection(CameraSettings& camera, const Sphere& sphere) {
  const CameraSettings before = camera;
  const glm::vec3 offset = camera.eye - camera.reference;
  const float tanTheta = std::tan(glm::radians(camera.halfAngleDeg));
  if (camera.projection == ProjectionKind::Perspective) {
    camera.projection = ProjectionKind::Parallel;
    if (isUsable(offset)) camera.parallelWidth = std::clamp(2.0f * glm::length(offset) * tanTheta, 1e-6f, 1e9f);
  } else {
    camera.projection = ProjectionKind::Perspective;
    if (isUsable(offset)) camera.eye = camera.reference + glm::normalize(offset) * (camera.parallelWidth / (2.0f * tanTheta));
  }
  moveDepthRange(camera, before, sphere);
}

void moveDepthRange(CameraSettings& camera, const CameraSettings& before, const Sphere& sphere) {
  const float delta = depthOf(camera, sphere.center) - depthOf(before, sphere.center);
  if (!std::isfinite(delta)) return;
  camera.far = std::clamp(camera.far + delta, 1e-5f, 1e9f);
  camera.near = std::clamp(camera.near + delta, camera.far * 1e-3f, camera.far * 0.999f);
}

}  // namespace facet::viewer
