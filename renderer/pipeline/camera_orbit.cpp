#include "pipeline/camera_orbit.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

namespace facet {

glm::vec3 orbitEye(glm::vec3 eye, glm::vec3 reference, glm::vec3 up, const CameraOrbit& orbit) {
  if (!orbit.moves()) return eye;
  // In double: a turntable's frames turn one camera many times, and a float
  // round trip through angles would drift its distance.
  const glm::dvec3 center(reference);
  const glm::dvec3 offset = glm::dvec3(eye) - center;
  const double distance = glm::length(offset);
  const double upLength = glm::length(glm::dvec3(up));
  if (!(distance > 0.0) || !(upLength > 0.0) || !std::isfinite(distance) || !std::isfinite(upLength))
    return eye;  // no view to move; buildFrameInputs names the problem
  const glm::dvec3 u = glm::dvec3(up) / upLength;
  glm::dvec3 direction = offset / distance;  // from P_ref toward P_eye
  const double height = glm::dot(direction, u);
  const glm::dvec3 level = direction - height * u;  // the part perpendicular to v_up
  const double levelLength = glm::length(level);
  if ((orbit.azimuthDeg != 0.0 || orbit.elevationDeg != 0.0) && levelLength > 1e-9) {
    // Longitude and latitude about v_up: azimuth turns the one, elevation
    // the other, so the two commute.
    const double azimuth = glm::radians(std::remainder(orbit.azimuthDeg, 360.0));
    const glm::dvec3 h = level / levelLength;
    const glm::dvec3 turned = std::cos(azimuth) * h + std::sin(azimuth) * glm::cross(u, h);
    double latitude = std::atan2(height, levelLength);
    if (orbit.elevationDeg != 0.0) {
      const double limit = glm::radians(kMaxOrbitLatitudeDeg);
      latitude = std::clamp(latitude + glm::radians(orbit.elevationDeg), -limit, limit);
    }
    direction = std::cos(latitude) * turned + std::sin(latitude) * u;
  }
  return glm::vec3(center + direction * (distance / orbit.zoom));
}

CameraSettings orbitCamera(const CameraSettings& camera, const CameraOrbit& orbit) {
  CameraSettings out = camera;
  out.source = Source::Manual;
  if (!orbit.moves()) return out;
  out.eye = orbitEye(camera.eye, camera.reference, camera.up, orbit);
  if (orbit.zoom == 1.0) return out;  // turning keeps the distance, and so the depths
  const double distance = glm::length(glm::dvec3(camera.eye) - glm::dvec3(camera.reference));
  const double moved = distance - distance / orbit.zoom;  // toward P_ref; < 0: away
  // What lay at depth t now lies at t - moved. Far never comes nearer than
  // far / zoom; near no nearer than far' / 1000, the auto camera's floor for
  // the depth buffer's precision, once the eye has gone into the scene.
  out.far = static_cast<float>(std::max(camera.far - moved, camera.far / orbit.zoom));
  out.near = static_cast<float>(std::max(camera.near - moved, out.far * 1e-3));
  if (camera.focusDistance > 0.0f) out.focusDistance = static_cast<float>(std::max(camera.focusDistance - moved, 0.0));  // behind the eye: autofocus
  if (camera.projection == ProjectionKind::Parallel) out.parallelWidth = static_cast<float>(camera.parallelWidth / orbit.zoom);
  return out;
}

}  // namespace facet
