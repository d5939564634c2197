// The primitive tests on their own: the watertight triangle test at known
// points, on its edges and through its double-precision fallback, over a
// flat grid and a closed mesh with rays through shared corners and edges;
// the sphere test from outside, inside and at its silhouette, its near root
// where the textbook formula cancels; the open interval (tMin, tMax).
#include <bit>
#include <cmath>
#include <limits>
#include <random>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "ray/brute_force.h"
#include "ray/sphere_intersection.h"
#include "ray/triangle_intersection.h"
#include "ray_test_scenes.h"

using namespace facet::ray;

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

bool hitTriangle(const Ray& ray, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, TriangleHit& hit) {
  return intersectTriangle(makeWatertightRay(ray), p0, p1, p2, hit);
}

bool hitTriangle(const Ray& ray, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2) {
  TriangleHit hit;
  return hitTriangle(ray, p0, p1, p2, hit);
}

// A grid of n x n cells of side 1/4 around the origin, each cut in two
// along alternating diagonals, in the plane where coordinate `normal` is 0.
// Every coordinate is a multiple of 1/8, so rays with such origins and
// directions are sheared exactly and hit corners and edges exactly.
struct Grid {
  Primitives primitives;
  std::vector<glm::vec3> targets;  // the corners and the edges' midpoints
};

Grid flatGrid(int n, int normal) {
  const int u = (normal + 1) % 3, v = (normal + 2) % 3;
  auto at = [&](float x, float y) {
    glm::vec3 p(0.0f);
    p[u] = x, p[v] = y;
    return p;
  };
  const float cell = 0.25f, origin = -0.5f * cell * static_cast<float>(n);
  Grid g;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float x0 = origin + cell * static_cast<float>(i), y0 = origin + cell * static_cast<float>(j);
      const glm::vec3 a = at(x0, y0), b = at(x0 + cell, y0), c = at(x0 + cell, y0 + cell), d = at(x0, y0 + cell);
      if ((i + j) % 2 == 0) g.primitives.triangleCorners.insert(g.primitives.triangleCorners.end(), {a, b, c, a, c, d});
      else g.primitives.triangleCorners.insert(g.primitives.triangleCorners.end(), {a, b, d, b, c, d});
    }
  // Inner corners and edge midpoints only: on the border a ray may leave.
  for (int j = 1; j < 2 * n; ++j)
    for (int i = 1; i < 2 * n; ++i) g.targets.push_back(at(origin + 0.5f * cell * static_cast<float>(i), origin + 0.5f * cell * static_cast<float>(j)));
  return g;
}

}  // namespace

TEST_CASE("triangle: a ray hits at the known t and barycentrics, from either side and with any direction length") {
  const glm::vec3 p0(0, 0, -2), p1(4, 0, -2), p2(0, 4, -2);
  TriangleHit hit;
  // P = (1, 2, -2) = (1 - u - v)·p0 + u·p1 + v·p2 with u = 1/4, v = 1/2.
  REQUIRE(hitTriangle(Ray{{1, 2, 0}, {0, 0, -1}}, p0, p1, p2, hit));
  CHECK(hit.t == 2.0f);
  CHECK(hit.u == 0.25f);
  CHECK(hit.v == 0.5f);
  REQUIRE(hitTriangle(Ray{{1, 2, 0}, {0, 0, -0.5f}}, p0, p1, p2, hit));
  CHECK(hit.t == 4.0f);  // t counts lengths of the direction
  REQUIRE(hitTriangle(Ray{{1, 2, -5}, {0, 0, 3}}, p0, p1, p2, hit));  // the back face
  CHECK(hit.t == 1.0f);
  CHECK(hit.u == 0.25f);
  CHECK(hit.v == 0.5f);
  // Slanted, dominant axis x: P = (1, 1, -2), u = v = 1/4.
  REQUIRE(hitTriangle(Ray{{-7, 0, -3}, {8, 1, 1}}, p0, p1, p2, hit));
  CHECK(hit.t == 1.0f);
  CHECK(hit.u == 0.25f);
  CHECK(hit.v == 0.25f);
  // The same corners in another order: the barycentrics follow the corners.
  REQUIRE(hitTriangle(Ray{{1, 2, 0}, {0, 0, -1}}, p1, p2, p0, hit));
  CHECK(hit.u == 0.5f);
  CHECK(hit.v == 0.25f);
}

TEST_CASE("triangle: tMin and tMax are open bounds") {
  const glm::vec3 p0(0, 0, -2), p1(4, 0, -2), p2(0, 4, -2);
  const glm::vec3 o(1, 2, 0), d(0, 0, -1);
  CHECK(hitTriangle(Ray{o, d, 0.0f, kInfinity}, p0, p1, p2));
  CHECK_FALSE(hitTriangle(Ray{o, d, 0.0f, 2.0f}, p0, p1, p2));
  CHECK(hitTriangle(Ray{o, d, 0.0f, std::nextafter(2.0f, kInfinity)}, p0, p1, p2));
  CHECK_FALSE(hitTriangle(Ray{o, d, 2.0f, kInfinity}, p0, p1, p2));
  CHECK(hitTriangle(Ray{o, d, std::nextafter(2.0f, 0.0f), kInfinity}, p0, p1, p2));
  CHECK_FALSE(hitTriangle(Ray{o, -d, 0.0f, kInfinity}, p0, p1, p2));  // behind the origin
  CHECK(hitTriangle(Ray{o, -d, -kInfinity, kInfinity}, p0, p1, p2));  // unless the interval reaches back
}

TEST_CASE("triangle: what is not there is never hit: beside it, edge-on, no area, a NaN or infinite corner, no direction") {
  const glm::vec3 p0(0, 0, -2), p1(4, 0, -2), p2(0, 4, -2);
  CHECK_FALSE(hitTriangle(Ray{{3, 3, 0}, {0, 0, -1}}, p0, p1, p2));     // beside the hypotenuse
  CHECK_FALSE(hitTriangle(Ray{{-1, 1, -2}, {1, 0, 0}}, p0, p1, p2));    // in its plane, through it
  CHECK_FALSE(hitTriangle(Ray{{1, 1, 0}, {0, 0, -1}}, p0, p0 + glm::vec3(1, 1, 0), p0 + glm::vec3(2, 2, 0)));  // collinear, on the ray
  CHECK_FALSE(hitTriangle(Ray{{0, 0, 0}, {0, 0, -1}}, p0, p0, p0));    // a point, on the ray
  for (const float bad : {kNaN, kInfinity, -kInfinity})
    for (int corner = 0; corner < 3; ++corner)
      for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 p[3] = {p0, p1, p2};
        p[corner][axis] = bad;
        CHECK_FALSE(hitTriangle(Ray{{1, 1, 0}, {0, 0, -1}}, p[0], p[1], p[2]));
      }
  CHECK_FALSE(hitTriangle(Ray{{1, 1, 0}, {0, 0, 0}}, p0, p1, p2));
  CHECK_FALSE(hitTriangle(Ray{{1, 1, 0}, {0, 0, kNaN}}, p0, p1, p2));
  CHECK_FALSE(hitTriangle(Ray{{1, kNaN, 0}, {0, 0, -1}}, p0, p1, p2));
}

TEST_CASE("triangle: an edge function the float products round to 0 is decided in double: a hair outside misses, the neighbour hits") {
  // Ray from the origin along +z: the shear is the identity, the edge
  // functions are those of the corners' x, y. For edge B C,
  // Cx·By = (1 + 2^-15)² = 1 + 2^-14 + 2^-30 rounds to 1 + 2^-14 = Cy·Bx, so
  // U is 0 in float and -2^-30 exactly: the origin lies just outside the
  // triangle A B C, and just inside D C B across that edge.
  const float e15 = 0x1p-15f, e14 = 0x1p-14f;
  const glm::vec3 A(1, -1, 1), B(-1, -(1 + e15), 1), C(1 + e15, 1 + e14, 1), D(-1, 1, 1);
  REQUIRE(C.x * B.y == C.y * B.x);  // the float products agree
  REQUIRE(static_cast<double>(C.x) * B.y - static_cast<double>(C.y) * B.x == -0x1p-30);  // the exact ones do not
  const Ray ray{{0, 0, 0}, {0, 0, 1}};
  CHECK_FALSE(hitTriangle(ray, A, B, C));
  CHECK(hitTriangle(ray, D, C, B));
}

TEST_CASE("triangle: rays exactly through the corners and edges of a flat grid all hit it") {
  // Dominant axis along the normal, and slanted ones where the dominant axis
  // lies in the plane; up and down (the winding swap).
  const glm::vec3 directions[] = {{0, 0, -1}, {0, 0, 1},         {0.25f, 0.5f, -1},  {-0.5f, 0.25f, 1}, {0.125f, -1, 0.5f},
                                  {1, 0.5f, -0.25f}, {-1, -0.75f, 0.5f}, {0.5f, 0.5f, -0.5f}};
  int rays = 0;
  for (int normal = 0; normal < 3; ++normal) {
    const Grid grid = flatGrid(8, normal);
    for (glm::vec3 d : directions) {
      // The example directions are for a grid in z = 0; turn them with it.
      glm::vec3 direction;
      for (int a = 0; a < 3; ++a) direction[(normal + 1 + a) % 3] = d[a];
      for (const glm::vec3& target : grid.targets) {
        const Ray ray{target - 3.0f * direction, direction};
        Hit hit;
        CAPTURE(normal);
        CAPTURE(target.x);
        CAPTURE(target.y);
        CAPTURE(target.z);
        CAPTURE(direction.x);
        CAPTURE(direction.y);
        CAPTURE(direction.z);
        CHECK(intersectBruteForce(grid.primitives, ray, hit));
        CHECK(hit.t == 3.0f);
        ++rays;
      }
    }
  }
  CHECK(rays == 3 * 8 * 15 * 15);
}

TEST_CASE("triangle: rays from inside a closed mesh never leak, aimed at random, at its vertices and at its edges") {
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    const test::ClosedMesh mesh = test::icosphere(3, seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    auto inside = [&] {
      for (;;) {
        const glm::vec3 p(unit(rng), unit(rng), unit(rng));
        if (glm::length(p) < 1.0f) return mesh.centre + 0.5f * mesh.inradius * p;
      }
    };
    std::vector<Ray> rays;
    for (const glm::vec3& v : mesh.vertices) {
      const glm::vec3 o = inside();
      rays.push_back(Ray{o, v - o});
    }
    for (const auto& [a, b] : mesh.edges) {
      const glm::vec3 o = inside();
      rays.push_back(Ray{o, 0.5f * (mesh.vertices[a] + mesh.vertices[b]) - o});
      // and a point along the edge at a fraction no power of two gives
      rays.push_back(Ray{o, mesh.vertices[a] + 0.3f * (mesh.vertices[b] - mesh.vertices[a]) - o});
    }
    for (int k = 0; k < 2000; ++k) rays.push_back(Ray{inside(), glm::vec3(unit(rng), unit(rng), unit(rng))});
    int leaks = 0;
    for (const Ray& ray : rays) {
      Hit hit;
      if (!intersectBruteForce(mesh.primitives, ray, hit)) ++leaks;
    }
    CAPTURE(seed);
    CHECK(leaks == 0);
  }
}

TEST_CASE("sphere: from outside the hit is at the distance minus the radius, in lengths of the direction") {
  const glm::vec3 centre(0, 0, -5);
  float t = 0;
  REQUIRE(intersectSphere(Ray{{0, 0, 0}, {0, 0, -1}}, centre, 1.0f, t));
  CHECK(t == 4.0f);
  REQUIRE(intersectSphere(Ray{{0, 0, 0}, {0, 0, -2}}, centre, 1.0f, t));
  CHECK(t == 2.0f);
  REQUIRE(intersectSphere(Ray{{0, 0, 0}, {0, 0, -1}}, centre, -1.0f, t));  // the radius's sign does not matter
  CHECK(t == 4.0f);
  CHECK_FALSE(intersectSphere(Ray{{0, 0, 0}, {0, 0, 1}}, centre, 1.0f, t));  // behind
}

TEST_CASE("sphere: from inside the ray hits the far side") {
  const glm::vec3 centre(0, 0, -5);
  float t = 0;
  REQUIRE(intersectSphere(Ray{centre, {0, 0, -1}}, centre, 1.0f, t));
  CHECK(t == 1.0f);
  REQUIRE(intersectSphere(Ray{{0, 0, -5.5f}, {0, 0, -1}}, centre, 1.0f, t));
  CHECK(t == 0.5f);
  REQUIRE(intersectSphere(Ray{{0, 0, -5.5f}, {0, 0, 1}}, centre, 1.0f, t));
  CHECK(t == 1.5f);
}

TEST_CASE("sphere: the silhouette: just inside it hits, just outside it misses, tangent-ish misses stay misses") {
  const glm::vec3 centre(0, 0, -5);
  float t = 0;
  CHECK(intersectSphere(Ray{{0.999999f, 0, 0}, {0, 0, -1}}, centre, 1.0f, t));
  CHECK(t == doctest::Approx(5.0f - std::sqrt(1.0f - 0.999999f * 0.999999f)).epsilon(1e-4));
  CHECK_FALSE(intersectSphere(Ray{{1.000001f, 0, 0}, {0, 0, -1}}, centre, 1.0f, t));
  // Far away and grazing: in double the decision stays on the right side.
  const float r = 1000.0f;
  CHECK(intersectSphere(Ray{{std::nextafter(r, 0.0f), 0, 1e6f}, {0, 0, -1}}, glm::vec3(0), r, t));
  CHECK_FALSE(intersectSphere(Ray{{std::nextafter(r, kInfinity), 0, 1e6f}, {0, 0, -1}}, glm::vec3(0), r, t));
}

TEST_CASE("sphere: tMin and tMax are open bounds, and a near root outside them gives way to the far one") {
  const glm::vec3 centre(0, 0, -5);
  const Ray ray{{0, 0, 0}, {0, 0, -1}};
  float t = 0;
  CHECK_FALSE(intersectSphere(Ray{ray.origin, ray.direction, 0.0f, 4.0f}, centre, 1.0f, t));
  REQUIRE(intersectSphere(Ray{ray.origin, ray.direction, 4.0f, kInfinity}, centre, 1.0f, t));
  CHECK(t == 6.0f);
  CHECK_FALSE(intersectSphere(Ray{ray.origin, ray.direction, 6.0f, kInfinity}, centre, 1.0f, t));
  REQUIRE(intersectSphere(Ray{ray.origin, ray.direction, 0.0f, std::nextafter(4.0f, kInfinity)}, centre, 1.0f, t));
  CHECK(t == 4.0f);
}

TEST_CASE("sphere: the near root of a ray starting just outside a large sphere is exact to the float (the stable quadratic)") {
  // Radius R = 10^6, the ray along -z at height h beside the axis, starting
  // level with the centre's top: the near root is R - sqrt(R² - h²) =
  // h²/(R + sqrt(R² - h²)), about h²/2R. The textbook (-B - sqrt(disc))/2A
  // subtracts two numbers near 2R and keeps ~12 fewer digits than it needs;
  // q = -(B + sign(B)·sqrt(disc))/2 and t = C'/q subtract nothing.
  const float R = 1e6f;
  for (const float h : {1.0f, 3.0f, 1.25f, 20.0f}) {  // h² a multiple of 2^-12: C' = |O - C|² - R² is exact
    const glm::vec3 centre(0, 0, -R);
    float t = 0;
    REQUIRE(intersectSphere(Ray{{0, h, 0}, {0, 0, -1}}, centre, R, t));
    const long double hh = static_cast<long double>(h) * h, RR = static_cast<long double>(R);
    const float exact = static_cast<float>(hh / (RR + std::sqrt(RR * RR - hh)));
    CAPTURE(h);
    CHECK(std::fabs(t - exact) <= std::nextafter(exact, kInfinity) - exact);  // within one ulp
  }
}

TEST_CASE("sphere: radius 0 is hit only through its centre, and NaN and infinity hit nothing") {
  float t = 0;
  CHECK(intersectSphere(Ray{{0, 0, 0}, {0, 0, -1}}, glm::vec3(0, 0, -3), 0.0f, t));
  CHECK(t == 3.0f);
  CHECK_FALSE(intersectSphere(Ray{{0, 0.001f, 0}, {0, 0, -1}}, glm::vec3(0, 0, -3), 0.0f, t));
  CHECK_FALSE(intersectSphere(Ray{{0, 0, 0}, {0, 0, -1}}, glm::vec3(0, 0, -3), kNaN, t));
  CHECK_FALSE(intersectSphere(Ray{{0, 0, 0}, {0, 0, -1}}, glm::vec3(0, kNaN, -3), 1.0f, t));
  CHECK_FALSE(intersectSphere(Ray{{0, 0, 0}, {0, 0, 0}}, glm::vec3(0, 0, -3), 1.0f, t));
  CHECK_FALSE(intersectSphere(Ray{{0, 0, kInfinity}, {0, 0, -1}}, glm::vec3(0, 0, -3), 1.0f, t));
}
