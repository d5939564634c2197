// Each course matrix against the course's formula written out by hand.
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <string>

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "math/eye_matrix.h"
#include "math/normal_matrix.h"
#include "math/projection.h"
#include "math/transforms.h"
#include "math/viewport.h"

using namespace facet;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

glm::vec3 apply(const glm::mat4& m, glm::vec3 p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }

glm::vec3 project(const glm::mat4& m, glm::vec3 p) {
  const glm::vec4 c = m * glm::vec4(p, 1.0f);
  return glm::vec3(c) / c.w;
}

void checkNear(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
  CHECK(a.x == doctest::Approx(b.x).epsilon(eps));
  CHECK(a.y == doctest::Approx(b.y).epsilon(eps));
  CHECK(a.z == doctest::Approx(b.z).epsilon(eps));
}

void checkIdentity(const glm::mat4& m, float eps = 1e-5f) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) CHECK(m[c][r] == doctest::Approx(c == r ? 1.0f : 0.0f).epsilon(eps));
}

}  // namespace

TEST_CASE("translation and scaling move and stretch a point as written") {
  checkNear(apply(translation({1, -2, 3}), {4, 5, 6}), {5, 3, 9});
  checkNear(apply(scaling({2, 3, -1}), {4, 5, 6}), {8, 15, -6});
}

TEST_CASE("rotations about x, y, z follow the course's right-hand rule") {
  // Rz(90°): x -> y; Rx(90°): y -> z; Ry(90°): z -> x.
  checkNear(apply(rotationZ(kPi / 2), {1, 0, 0}), {0, 1, 0});
  checkNear(apply(rotationX(kPi / 2), {0, 1, 0}), {0, 0, 1});
  checkNear(apply(rotationY(kPi / 2), {0, 0, 1}), {1, 0, 0});
  // A general angle against cos/sin by hand: Rz(30°)·(2, 1, 5).
  const float c = std::cos(kPi / 6), s = std::sin(kPi / 6);
  checkNear(apply(rotationZ(kPi / 6), {2, 1, 5}), {2 * c - 1 * s, 2 * s + 1 * c, 5});
}

TEST_CASE("shear adds multiples of the other coordinates") {
  ShearFactors h;
  h.hxy = 2;
  h.hzx = -1;
  checkNear(apply(shear(h), {1, 3, 4}), {1 + 2 * 3, 3, 4 - 1});
}

TEST_CASE("GRM maps its rows i, j, k onto the x, y, z axes") {
  const glm::vec3 k = glm::normalize(glm::vec3(1, 2, 2));
  const glm::vec3 i = glm::normalize(glm::cross(glm::vec3(0, 1, 0), k));
  const glm::vec3 j = glm::cross(k, i);
  const glm::mat4 grm = generalRotation(i, j, k);
  checkNear(apply(grm, i), {1, 0, 0});
  checkNear(apply(grm, j), {0, 1, 0});
  checkNear(apply(grm, k), {0, 0, 1});
}

TEST_CASE("rotation about an arbitrary axis through a point") {
  const glm::vec3 point{1, 2, 3}, axis{0, 0, 1};
  // About the line x=1, y=2 (parallel to z) by 90°: (2, 2, 7) -> (1, 3, 7).
  checkNear(apply(rotationAboutAxis(point, axis, kPi / 2), {2, 2, 7}), {1, 3, 7});
  // Points on the axis stay put; a general axis agrees with glm's construction.
  const glm::vec3 tilted = glm::normalize(glm::vec3(1, -2, 0.5f));
  checkNear(apply(rotationAboutAxis(point, tilted, 0.7f), point + 3.0f * tilted), point + 3.0f * tilted);
  const glm::mat4 reference = glm::translate(glm::mat4(1), point) * glm::rotate(glm::mat4(1), 0.7f, tilted) * glm::translate(glm::mat4(1), -point);
  checkNear(apply(rotationAboutAxis(point, tilted, 0.7f), {4, -1, 2}), apply(reference, {4, -1, 2}));
}

TEST_CASE("course inverses multiply to the identity") {
  checkIdentity(translation({3, -4, 5}) * inverseTranslation({3, -4, 5}));
  checkIdentity(scaling({2, 0.5f, -4}) * inverseScaling({2, 0.5f, -4}));
  const glm::mat4 r = rotationX(0.3f) * rotationY(-1.1f) * rotationZ(2.0f);
  checkIdentity(r * inverseRotation(r));
  const glm::mat4 m = translation({1, 2, 3}) * rotationAboutAxis({0, 1, 0}, {1, 1, 1}, 0.4f) * scaling({2, 3, 4});
  checkIdentity(m * glm::inverse(m), 1e-4f);
}

TEST_CASE("eye matrix: P_eye to the origin, P_ref onto +z, +x to the right, +y up") {
  const glm::vec3 eye{5, 4, 7}, ref{0, 1, 0}, up{0, 1, 0};
  const glm::mat4 em = eyeMatrix(eye, ref, up);
  checkNear(apply(em, eye), {0, 0, 0});
  const glm::vec3 r = apply(em, ref);
  CHECK(r.x == doctest::Approx(0).epsilon(1e-5));
  CHECK(r.y == doctest::Approx(0).epsilon(1e-5));
  CHECK(r.z == doctest::Approx(glm::length(ref - eye)));
  // Looking down -z from +z in world space (the common default view), world +x
  // is to the right and world +y up: eye x and y keep their signs.
  const glm::mat4 front = eyeMatrix({0, 0, 10}, {0, 0, 0}, {0, 1, 0});
  checkNear(apply(front, {1, 0, 0}), {1, 0, 10});
  checkNear(apply(front, {0, 1, 0}), {0, 1, 10});
  // Mirror_x makes the frame left-handed: its determinant is -1.
  CHECK(glm::determinant(glm::mat3(em)) == doctest::Approx(-1.0f));
  CHECK(eyeFrameIsValid(eye, ref, up));
  CHECK_FALSE(eyeFrameIsValid(eye, eye, up));
  CHECK_FALSE(eyeFrameIsValid({0, 5, 0}, {0, 0, 0}, {0, 1, 0}));
}

TEST_CASE("an eye frame that is not defined says why") {
  const glm::vec3 up{0, 1, 0};
  CHECK(eyeFrameProblem({0, 0, 10}, {0, 0, 0}, up) == nullptr);
  CHECK(std::string(eyeFrameProblem({1, 2, 3}, {1, 2, 3}, up)) == "the eye is on the reference point");
  CHECK(std::string(eyeFrameProblem({0, 5, 0}, {0, 0, 0}, up)) == "up is along the line of sight");
  CHECK(std::string(eyeFrameProblem({0, 0, 10}, {0, 0, 0}, {0, 0, 0})) == "up is zero");
  // 1e30 is a float, but its square is not: k cannot be normalized. This was
  // reported as "eye on the reference point".
  CHECK(std::string(eyeFrameProblem({1e30f, 0, 0}, {0, 0, 0}, up)) == "the eye is too far from the reference point for float arithmetic, more than about 1.8e19");
  CHECK(eyeFrameProblem({1e18f, 0, 0}, {0, 0, 0}, up) == nullptr);
  CHECK(std::string(eyeFrameProblem({0, 0, 10}, {0, 0, 0}, {0, 1e30f, 0})).find("up is too long") == 0);
  CHECK(std::string(eyeFrameProblem({0, 0, INFINITY}, {0, 0, 0}, up)) == "eye, reference or up is not finite");
}

TEST_CASE("perspective: x' = x/(z tanθ), y' = A_R·y/(z tanθ), z' = A + B/z") {
  const float theta = kPi / 6, aspect = 1.5f, n = 0.5f, f = 20.0f;
  const glm::mat4 pm = perspective(theta, aspect, n, f);
  const float t = std::tan(theta), a = f / (f - n), b = -n * f / (f - n);
  const glm::vec3 p{1.2f, -0.7f, 4.0f};
  const glm::vec3 q = project(pm, p);
  CHECK(q.x == doctest::Approx(p.x / (p.z * t)));
  CHECK(q.y == doctest::Approx(aspect * p.y / (p.z * t)));
  CHECK(q.z == doctest::Approx(a + b / p.z));
  CHECK(project(pm, {0, 0, n}).z == doctest::Approx(0.0f).epsilon(1e-6));
  CHECK(project(pm, {0, 0, f}).z == doctest::Approx(1.0f));
  // The edge of the horizontal angle of view lands on x' = 1.
  CHECK(project(pm, {3.0f * t, 0, 3.0f}).x == doctest::Approx(1.0f));
}

TEST_CASE("parallel normalization matrix maps the box to x, y in [-1,1], z in [0,1]") {
  const glm::mat4 pm = parallel(8, 4, 1, 11);
  checkNear(project(pm, {4, 2, 1}), {1, 1, 0});
  checkNear(project(pm, {-4, -2, 11}), {-1, -1, 1});
  checkNear(project(pm, {1, -1, 6}), {0.25f, -0.5f, 0.5f});
}

TEST_CASE("window-to-viewport: [-1,1]² onto [0,W]×[0,H], lower-left origin") {
  const glm::mat4 m = viewportMatrix(640, 480);
  checkNear(apply(m, {-1, -1, 0.25f}), {0, 0, 0.25f});
  checkNear(apply(m, {1, 1, 0.75f}), {640, 480, 0.75f});
  checkNear(apply(m, {0, 0, 0}), {320, 240, 0});
  // The general course formula with an off-centre window and viewport.
  const glm::mat4 g = windowToViewport({2, 6, 1, 3}, {10, 30, 100, 200});
  checkNear(apply(g, {4, 2, 0}), {20, 150, 0});
}

TEST_CASE("normal matrix keeps normals perpendicular under non-uniform scaling") {
  const glm::mat4 tm = rotationY(0.5f) * scaling({4, 1, 1});
  const glm::vec3 tangent = glm::normalize(glm::vec3(1, 1, 0)), normal = glm::normalize(glm::vec3(1, -1, 0));
  const glm::vec3 worldTangent = glm::mat3(tm) * tangent;
  const glm::vec3 worldNormal = normalMatrix(tm) * normal;
  CHECK(glm::dot(worldTangent, worldNormal) == doctest::Approx(0.0f).epsilon(1e-6));
  CHECK(std::fabs(glm::dot(glm::normalize(glm::mat3(tm) * normal), glm::normalize(worldTangent))) > 0.1f);  // the naive way fails
}

TEST_CASE("course eye+perspective and glm::lookAt+perspectiveZO put a point on the same pixel") {
  const int width = 640, height = 480;
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const glm::vec3 eye{3, 2, 6}, ref{0, 0.5f, 0}, up{0, 1, 0};
  const float theta = glm::radians(35.0f), n = 0.3f, f = 50.0f;
  const glm::mat4 course = viewportMatrix(width, height) * perspective(theta, aspect, n, f) * eyeMatrix(eye, ref, up);
  // glm is right-handed and takes the vertical full angle: tan(fovy/2) = tanθ / A_R.
  const float fovy = 2.0f * std::atan(std::tan(theta) / aspect);
  const glm::mat4 reference = viewportMatrix(width, height) * glm::perspectiveZO(fovy, aspect, n, f) * glm::lookAtRH(eye, ref, up);
  for (const glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 2, -1), glm::vec3(-2, 0.3f, 1.5f)}) {
    const glm::vec3 a = project(course, p), b = project(reference, p);
    CHECK(a.x == doctest::Approx(b.x).epsilon(1e-4));
    CHECK(a.y == doctest::Approx(b.y).epsilon(1e-4));
    CHECK(a.z == doctest::Approx(b.z).epsilon(1e-4));
  }
}
