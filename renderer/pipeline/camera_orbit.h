#pragma once
// Moving a resolved camera about its reference point, as F3D's
// --camera-azimuth-angle, --camera-elevation-angle and --camera-zoom-factor
// do (VTK's vtkCamera::Azimuth, Elevation and Dolly): the command line's
// --camera-azimuth/-elevation/-zoom and render --turntable.
#include <glm/vec3.hpp>

#include "settings/render_settings.h"

namespace facet {

struct CameraOrbit {
  // About v_up through P_ref, right-handed: + carries the eye toward the
  // camera's right (eye +z, up +y, 90: the eye at +x), so the scene turns left.
  double azimuthDeg = 0.0;
  // About the camera's right axis (v_up × line of sight) through P_ref: + lifts
  // the eye toward v_up. The eye's latitude (its angle from the plane
  // perpendicular to v_up) stops at ±kMaxOrbitLatitudeDeg, so v_up never
  // becomes the line of sight.
  double elevationDeg = 0.0;
  // > 0: |P_eye - P_ref| divided by it (2: twice as close, the reference
  // plane twice as large).
  double zoom = 1.0;

  bool moves() const { return azimuthDeg != 0.0 || elevationDeg != 0.0 || zoom != 1.0; }
};

inline constexpr double kMaxOrbitLatitudeDeg = 89.0;  // as the viewer's drag (viewer/camera_controls.h)

// P_eye after `orbit`: azimuth (taken modulo 360), then elevation, then zoom.
// The reference point and v_up stay. An orbit that does not move returns
// `eye` unchanged, bit for bit. An eye whose line of sight lies along v_up
// has no azimuth or elevation to change and is only zoomed.
glm::vec3 orbitEye(glm::vec3 eye, glm::vec3 reference, glm::vec3 up, const CameraOrbit& orbit);

// A resolved camera after `orbit`, with source = manual: the eye moved
// (orbitEye). A zoom also moves near and far with the eye, so that what lay
// between them still does (near kept positive, at least far / 1000, once the
// eye has gone into the scene), moves a focus distance with it (0, autofocus,
// once the point in focus is behind the eye) and divides a parallel view's
// width, which magnifies as the perspective view's shorter distance does.
CameraSettings orbitCamera(const CameraSettings& camera, const CameraOrbit& orbit);

}  // namespace facet
