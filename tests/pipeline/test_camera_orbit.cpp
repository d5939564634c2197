// The camera moves of --camera-azimuth, --camera-elevation, --camera-zoom
// and render --turntable (pipeline/camera_orbit.h): F3D's (VTK's) sense of
// each angle, the clamp short of the pole, the zoom's distance and depths.
#include <cmath>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "math/eye_matrix.h"
#include "pipeline/camera_orbit.h"

using namespace facet;

namespace {

const glm::vec3 kOrigin{0.0f};
const glm::vec3 kUp{0.0f, 1.0f, 0.0f};

void checkNear(glm::vec3 got, glm::vec3 expected) {
  INFO("got (" << got.x << ", " << got.y << ", " << got.z << "), expected (" << expected.x << ", " << expected.y << ", " << expected.z << ")");
  CHECK(glm::length(got - expected) < 1e-5f);
}

CameraOrbit azimuth(double degrees) {
  CameraOrbit o;
  o.azimuthDeg = degrees;
  return o;
}

CameraOrbit elevation(double degrees) {
  CameraOrbit o;
  o.elevationDeg = degrees;
  return o;
}

CameraOrbit zoom(double factor) {
  CameraOrbit o;
  o.zoom = factor;
  return o;
}

// The eye's angle above the plane perpendicular to up (+y), seen from the origin, in degrees
// (atan2 in double: asin of a float near 1 would lose the hundredths near the pole).
double latitudeDeg(glm::vec3 eye) {
  const double x = eye.x, y = eye.y, z = eye.z;
  return glm::degrees(std::atan2(y, std::sqrt(x * x + z * z)));
}

}  // namespace

TEST_CASE("azimuth turns the eye about v_up, right-handed as VTK's: 90 carries the eye from +z to +x") {
  const glm::vec3 eye{0.0f, 0.0f, 5.0f};
  checkNear(orbitEye(eye, kOrigin, kUp, azimuth(90)), {5.0f, 0.0f, 0.0f});
  checkNear(orbitEye(eye, kOrigin, kUp, azimuth(-90)), {-5.0f, 0.0f, 0.0f});
  checkNear(orbitEye(eye, kOrigin, kUp, azimuth(180)), {0.0f, 0.0f, -5.0f});
  // Taken modulo 360: a whole turn is the start, -270 is +90.
  checkNear(orbitEye(eye, kOrigin, kUp, azimuth(360)), eye);
  CHECK(orbitEye(eye, kOrigin, kUp, azimuth(-270)) == orbitEye(eye, kOrigin, kUp, azimuth(90)));
  // About the reference point, whatever the length of v_up; the height above it stays.
  const glm::vec3 reference{1.0f, 2.0f, 3.0f};
  checkNear(orbitEye(reference + glm::vec3(0.0f, 1.0f, 4.0f), reference, {0.0f, 3.0f, 0.0f}, azimuth(90)), reference + glm::vec3(4.0f, 1.0f, 0.0f));
}

TEST_CASE("four quarter turns, as a 4-frame turntable's steps, bring the eye back") {
  glm::vec3 eye{3.0f, 2.0f, 4.0f};
  const glm::vec3 start = eye;
  for (int k = 0; k < 4; ++k) eye = orbitEye(eye, kOrigin, kUp, azimuth(90));
  checkNear(eye, start);
}

TEST_CASE("elevation lifts the eye toward v_up about the camera's right axis, and stops short of the pole") {
  const glm::vec3 eye{0.0f, 0.0f, 5.0f};
  const float s = 5.0f * std::sqrt(0.5f);
  checkNear(orbitEye(eye, kOrigin, kUp, elevation(45)), {0.0f, s, s});
  checkNear(orbitEye(eye, kOrigin, kUp, elevation(-45)), {0.0f, -s, s});
  // The longitude stays: an eye off the axes rises in its own vertical plane.
  const glm::vec3 slanted{3.0f, 1.0f, 4.0f};
  const glm::vec3 raised = orbitEye(slanted, kOrigin, kUp, elevation(30));
  CHECK(raised.x / raised.z == doctest::Approx(0.75));
  CHECK(glm::length(raised) == doctest::Approx(glm::length(slanted)));
  CHECK(latitudeDeg(raised) == doctest::Approx(latitudeDeg(slanted) + 30.0).epsilon(1e-5));
  // 90 and beyond: held at kMaxOrbitLatitudeDeg, so up is never the line of sight.
  for (const double asked : {90.0, 135.0, 400.0}) {
    const glm::vec3 top = orbitEye(eye, kOrigin, kUp, elevation(asked));
    CHECK(latitudeDeg(top) == doctest::Approx(kMaxOrbitLatitudeDeg).epsilon(1e-5));
    CHECK(top.z > 0.0f);  // not over the pole to the far side
    CHECK(eyeFrameIsValid(top, kOrigin, kUp));
  }
  CHECK(latitudeDeg(orbitEye(eye, kOrigin, kUp, elevation(-90))) == doctest::Approx(-kMaxOrbitLatitudeDeg).epsilon(1e-5));
}

TEST_CASE("azimuth and elevation commute: one orbit of both is the two one after the other") {
  const glm::vec3 eye{1.0f, 0.8f, 1.6f};
  CameraOrbit both;
  both.azimuthDeg = 40;
  both.elevationDeg = 25;
  checkNear(orbitEye(eye, kOrigin, kUp, both), orbitEye(orbitEye(eye, kOrigin, kUp, elevation(25)), kOrigin, kUp, azimuth(40)));
  checkNear(orbitEye(eye, kOrigin, kUp, both), orbitEye(orbitEye(eye, kOrigin, kUp, azimuth(40)), kOrigin, kUp, elevation(25)));
}

TEST_CASE("zoom divides the eye's distance from the reference point: 2 halves it, 0.5 doubles it") {
  const glm::vec3 reference{0.0f, 1.0f, 0.0f};
  const glm::vec3 eye{0.0f, 1.0f, 6.0f};
  checkNear(orbitEye(eye, reference, kUp, zoom(2)), {0.0f, 1.0f, 3.0f});
  checkNear(orbitEye(eye, reference, kUp, zoom(0.5)), {0.0f, 1.0f, 12.0f});
  // An eye straight above has no azimuth to turn; it is only zoomed.
  CameraOrbit both = zoom(2);
  both.azimuthDeg = 90;
  checkNear(orbitEye({0.0f, 4.0f, 0.0f}, kOrigin, kUp, both), {0.0f, 2.0f, 0.0f});
}

TEST_CASE("an orbit that does not move leaves the camera as it was, bit for bit, now manual") {
  CameraSettings c;
  c.source = Source::Auto;
  c.eye = {0.1f, 0.7f, 3.3f};
  const CameraSettings same = orbitCamera(c, CameraOrbit{});
  CHECK(same.source == Source::Manual);
  CHECK(same.eye == c.eye);
  CHECK(same.near == c.near);
  CHECK(same.far == c.far);
  CHECK(orbitEye(c.eye, c.reference, c.up, CameraOrbit{}) == c.eye);
}

TEST_CASE("a zoomed camera's near and far move with the eye, and a parallel view narrows") {
  CameraSettings c;
  c.eye = {0.0f, 0.0f, 10.0f};
  c.near = 8.0f;  // the auto camera's planes hug the scene's sphere
  c.far = 12.0f;
  c.parallelWidth = 4.0f;
  const CameraSettings closer = orbitCamera(c, zoom(2));
  checkNear(closer.eye, {0.0f, 0.0f, 5.0f});
  CHECK(closer.near == doctest::Approx(3.0));
  CHECK(closer.far == doctest::Approx(7.0));
  CHECK(closer.parallelWidth == 4.0f);  // perspective: the distance alone magnifies
  const CameraSettings farther = orbitCamera(c, zoom(0.5));
  CHECK(farther.near == doctest::Approx(18.0));
  CHECK(farther.far >= 22.0f);
  // Into the scene: near stays positive, at the auto camera's floor of far / 1000.
  c.near = 0.1f;
  c.far = 100.0f;
  c.eye = {0.0f, 0.0f, 5.0f};
  const CameraSettings inside = orbitCamera(c, zoom(2));
  CHECK(inside.far == doctest::Approx(97.5));
  CHECK(inside.near == doctest::Approx(0.0975));
  c.projection = ProjectionKind::Parallel;
  CHECK(orbitCamera(c, zoom(2)).parallelWidth == doctest::Approx(2.0));
  // Turning alone keeps every depth.
  const CameraSettings turned = orbitCamera(c, azimuth(30));
  CHECK(turned.near == c.near);
  CHECK(turned.far == c.far);
  CHECK(turned.parallelWidth == c.parallelWidth);
}
