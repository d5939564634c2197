// The ray tests' scenes and rays (ray_test_scenes.h): seeded, so a failure
// names a scene that can be built again.
#include "ray_test_scenes.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <random>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

namespace facet::ray::test {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

struct Random {
  std::mt19937 engine;
  explicit Random(std::uint32_t seed) : engine(seed) {}

  float uniform(float a, float b) { return std::uniform_real_distribution<float>(a, b)(engine); }
  float logUniform(float a, float b) { return std::exp(uniform(std::log(a), std::log(b))); }
  int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(engine); }
  bool chance(float p) { return uniform(0.0f, 1.0f) < p; }
  glm::vec3 inBox(float half) { return glm::vec3(uniform(-half, half), uniform(-half, half), uniform(-half, half)); }
  glm::vec3 unitVector() {
    std::normal_distribution<float> n;
    for (;;) {
      const glm::vec3 v(n(engine), n(engine), n(engine));
      const float l = glm::length(v);
      if (l > 1e-3f) return v / l;
    }
  }
};

void addTriangle(Primitives& p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  p.triangleCorners.insert(p.triangleCorners.end(), {a, b, c});
}

void addRandomTriangle(Primitives& p, Random& r, glm::vec3 centre, float size) {
  addTriangle(p, centre + size * r.unitVector(), centre + size * r.unitVector(), centre + size * r.unitVector());
}

// One awkward triangle or sphere.
void addSliver(Primitives& p, Random& r, glm::vec3 at) {
  switch (r.below(7)) {
    case 0: {  // a needle: two corners 1e-4 apart, the third far
      const glm::vec3 a = at, b = at + 1e-4f * r.unitVector();
      addTriangle(p, a, b, at + r.uniform(1.0f, 8.0f) * r.unitVector());
      break;
    }
    case 1: {  // flat in an axis plane: the box has no thickness
      const int axis = r.below(3);
      glm::vec3 a = at + r.unitVector(), b = at + r.unitVector(), c = at + r.unitVector();
      a[axis] = b[axis] = c[axis] = at[axis];
      addTriangle(p, a, b, c);
      break;
    }
    case 2: {  // collinear: no area
      const glm::vec3 d = r.unitVector() * r.uniform(0.1f, 2.0f);
      addTriangle(p, at, at + d, at + 2.0f * d);
      break;
    }
    case 3:  // a point
      addTriangle(p, at, at, at);
      break;
    case 4:  // a sphere of radius 0
      p.spheres.emplace_back(at, 0.0f);
      break;
    case 5: {  // a right triangle in an axis plane with axis-aligned legs
      const int axis = r.below(3), u = (axis + 1) % 3, v = (axis + 2) % 3;
      glm::vec3 b = at, c = at;
      b[u] += r.uniform(0.1f, 2.0f);
      c[v] += r.uniform(0.1f, 2.0f);
      addTriangle(p, at, b, c);
      break;
    }
    default:  // a tiny sphere
      p.spheres.emplace_back(at, r.logUniform(1e-5f, 1e-2f));
      break;
  }
}

// Spheres are appended after all triangles here so a scene's indices are
// in the primitives' own order: triangles, then spheres.
Primitives scattered(Random& r, int count) {
  Primitives p;
  for (int i = 0; i < count; ++i) {
    if (i % 8 == 7) p.spheres.emplace_back(r.inBox(10.0f), r.logUniform(1e-3f, 2.0f));
    else addRandomTriangle(p, r, r.inBox(10.0f), r.logUniform(1e-3f, 5.0f));
  }
  return p;
}

Primitives clustered(Random& r, int count) {
  Primitives p;
  std::vector<glm::vec3> centres;
  for (int k = 0; k < 6; ++k) centres.push_back(r.inBox(8.0f));
  std::normal_distribution<float> spread(0.0f, 0.05f);
  for (int i = 0; i < count; ++i) {
    const glm::vec3 c = centres[static_cast<std::size_t>(r.below(6))] + glm::vec3(spread(r.engine), spread(r.engine), spread(r.engine));
    if (i % 50 == 0) addRandomTriangle(p, r, r.inBox(5.0f), 10.0f);
    else if (i % 9 == 0) p.spheres.emplace_back(c, r.logUniform(1e-3f, 0.05f));
    else addRandomTriangle(p, r, c, r.logUniform(1e-3f, 0.05f));
  }
  return p;
}

Primitives coincident(Random& r, int count) {
  Primitives prototypes = scattered(r, count / 6);
  for (int k = 0; k < 4; ++k) addSliver(prototypes, r, r.inBox(6.0f));
  Primitives p;
  const int triangles = static_cast<int>(prototypes.triangleCount()), spheres = static_cast<int>(prototypes.sphereCount());
  for (int i = 0; i < count; ++i) {
    if (i % 7 == 6 && spheres > 0) {
      p.spheres.push_back(prototypes.spheres[static_cast<std::size_t>(r.below(spheres))]);
    } else {
      const auto t = static_cast<std::size_t>(r.below(triangles));
      addTriangle(p, prototypes.triangleCorners[3 * t], prototypes.triangleCorners[3 * t + 1], prototypes.triangleCorners[3 * t + 2]);
    }
  }
  // A pile of one triangle: every centroid at one point.
  const glm::vec3 a = r.inBox(5.0f), b = a + r.unitVector(), c = a + r.unitVector();
  for (int i = 0; i < 24; ++i) addTriangle(p, a, b, c);
  return p;
}

Primitives slivers(Random& r, int count) {
  Primitives p;
  for (int i = 0; i < count; ++i) addSliver(p, r, r.inBox(8.0f));
  return p;
}

Primitives broken(Random& r, int count) {
  Primitives p = r.chance(0.5f) ? slivers(r, count) : scattered(r, count);
  const float bad[] = {kNaN, kInfinity, -kInfinity};
  for (glm::vec3& corner : p.triangleCorners)
    if (r.chance(0.02f)) corner[r.below(3)] = bad[r.below(3)];
  for (glm::vec4& s : p.spheres)
    if (r.chance(0.1f)) s[r.below(4)] = bad[r.below(3)];
  p.spheres.emplace_back(1.0f, 2.0f, 3.0f, 3e38f);  // reaches beyond float's range
  p.spheres.emplace_back(3e38f, 0.0f, 0.0f, 1e38f);
  addTriangle(p, glm::vec3(1e30f, 0.0f, 0.0f), glm::vec3(0.0f, 1e30f, 0.0f), glm::vec3(0.0f, 0.0f, 1e30f));  // huge but finite
  return p;
}

}  // namespace

Primitives randomScene(SceneKind kind, std::uint32_t seed, int count) {
  Random r(seed);
  switch (kind) {
    case SceneKind::Scattered: return scattered(r, count);
    case SceneKind::Clustered: return clustered(r, count);
    case SceneKind::Coincident: return coincident(r, count);
    case SceneKind::Slivers: return slivers(r, count);
    case SceneKind::Broken: return broken(r, count);
  }
  return {};
}

std::vector<Ray> randomRays(const Primitives& primitives, std::uint32_t seed, int count) {
  Random r(seed);
  // Aim at what is there: finite corners and centres.
  std::vector<glm::vec3> corners, centres;
  Bounds scene;
  for (std::uint32_t i = 0; i < primitives.count(); ++i) {
    Bounds b;
    if (!primitiveBounds(primitives, i, b)) continue;
    if (glm::length(b.upper - b.lower) > 1e3f) continue;  // the huge ones would stretch the box
    scene.grow(b);
    if (primitives.isSphere(i)) centres.push_back(glm::vec3(primitives.spheres[i - primitives.triangleCount()]));
    else for (std::size_t k = 0; k < 3; ++k) corners.push_back(primitives.triangleCorners[3 * i + k]);
  }
  if (scene.empty()) scene.grow(glm::vec3(-1.0f)), scene.grow(glm::vec3(1.0f));
  const glm::vec3 middle = 0.5f * (scene.lower + scene.upper);
  const float reach = glm::length(scene.upper - scene.lower);
  auto anyCorner = [&] { return corners.empty() ? middle : corners[static_cast<std::size_t>(r.below(static_cast<int>(corners.size())))]; };
  auto anyCentre = [&] { return centres.empty() ? middle : centres[static_cast<std::size_t>(r.below(static_cast<int>(centres.size())))]; };
  auto anyEdgeMidpoint = [&] {
    if (corners.size() < 3) return middle;
    const std::size_t t = static_cast<std::size_t>(r.below(static_cast<int>(corners.size() / 3))) * 3;
    const std::size_t k = static_cast<std::size_t>(r.below(3));
    return 0.5f * (corners[t + k] + corners[t + (k + 1) % 3]);
  };

  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    Ray ray;
    switch (r.below(4)) {
      case 0: ray.origin = middle + r.uniform(0.0f, 0.5f) * reach * r.unitVector(); break;
      case 1: ray.origin = middle + reach * r.unitVector(); break;  // outside
      case 2: ray.origin = anyCorner(); break;                       // on a triangle
      default: ray.origin = r.inBox(0.6f * reach) + middle; break;
    }
    switch (r.below(8)) {
      case 0:
      case 1: ray.direction = r.unitVector() * r.logUniform(1e-2f, 1e2f); break;
      case 2: {  // along one axis; the zero components +0 or -0
        const int axis = r.below(3);
        for (int a = 0; a < 3; ++a) ray.direction[a] = r.chance(0.5f) ? -0.0f : 0.0f;
        ray.direction[axis] = r.chance(0.5f) ? 1.0f : -1.0f;
        break;
      }
      case 3: {  // in an axis plane
        ray.direction = r.unitVector();
        ray.direction[r.below(3)] = r.chance(0.5f) ? -0.0f : 0.0f;
        break;
      }
      case 4: ray.direction = anyCorner() - ray.origin; break;
      case 5: ray.direction = anyEdgeMidpoint() - ray.origin; break;
      case 6: ray.direction = anyCentre() - ray.origin; break;
      default: {  // from a corner's axis-aligned neighbourhood straight at it
        const glm::vec3 target = anyCorner();
        const int axis = r.below(3);
        ray.origin = target;
        ray.origin[axis] -= r.chance(0.5f) ? reach : -reach;
        ray.direction = target - ray.origin;
        break;
      }
    }
    if (r.chance(0.2f)) {
      ray.tMin = r.chance(0.5f) ? -kInfinity : r.uniform(-1.0f, 1.0f);
      ray.tMax = r.chance(0.3f) ? kInfinity : ray.tMin + r.logUniform(1e-3f, 10.0f);
    }
    if (i % 500 == 499) {  // the broken rays
      const float bad[] = {kNaN, kInfinity, 0.0f};
      switch (r.below(3)) {
        case 0: ray.origin[r.below(3)] = bad[r.below(2)]; break;
        case 1: ray.direction[r.below(3)] = bad[r.below(2)]; break;
        default: ray.direction = glm::vec3(bad[2]); break;
      }
    }
    rays.push_back(ray);
  }
  return rays;
}

ClosedMesh icosphere(int subdivisions, std::uint32_t seed) {
  const float g = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<glm::dvec3> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                               {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  for (glm::dvec3& p : v) p = glm::normalize(p);
  std::vector<std::uint32_t> faces = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
                                      3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      v.push_back(glm::normalize(v[a] + v[b]));
      return midpoints[key] = static_cast<std::uint32_t>(v.size() - 1);
    };
    std::vector<std::uint32_t> next;
    for (std::size_t f = 0; f < faces.size(); f += 3) {
      const std::uint32_t a = faces[f], b = faces[f + 1], c = faces[f + 2];
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    faces = std::move(next);
  }

  // Off the axes: a rotation, a radius that is no power of two, a centre
  // away from the origin; rounded to float once per vertex.
  Random r(seed);
  const glm::dvec3 axis = glm::dvec3(r.unitVector());
  const double angle = r.uniform(0.3f, 2.8f), c = std::cos(angle), s = std::sin(angle);
  const glm::dmat3 k(0, axis.z, -axis.y, -axis.z, 0, axis.x, axis.y, -axis.x, 0);
  const glm::dmat3 rotation = glm::dmat3(1.0) + s * k + (1 - c) * (k * k);  // Rodrigues
  const double radius = r.uniform(1.3f, 3.7f);
  ClosedMesh mesh;
  mesh.centre = r.inBox(5.0f);
  for (const glm::dvec3& p : v) mesh.vertices.push_back(glm::vec3(glm::dvec3(mesh.centre) + radius * (rotation * p)));
  for (std::size_t f = 0; f < faces.size(); f += 3)
    for (std::size_t e = 0; e < 3; ++e) {
      mesh.primitives.triangleCorners.push_back(mesh.vertices[faces[f + e]]);
      const std::uint32_t a = faces[f + e], b = faces[f + (e + 1) % 3];
      if (a < b) mesh.edges.emplace_back(a, b);  // each edge once: its two faces run it opposite ways
    }
  // The icosahedron's inradius over its circumradius is 0.7947; subdividing only adds volume.
  mesh.inradius = static_cast<float>(0.79 * radius);
  return mesh;
}

bool sameHit(const Hit& a, const Hit& b) {
  return a.primitive == b.primitive && std::bit_cast<std::uint32_t>(a.t) == std::bit_cast<std::uint32_t>(b.t) &&
         std::bit_cast<std::uint32_t>(a.u) == std::bit_cast<std::uint32_t>(b.u) && std::bit_cast<std::uint32_t>(a.v) == std::bit_cast<std::uint32_t>(b.v);
}

}  // namespace facet::ray::test
