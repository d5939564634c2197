// Marching cubes on analytic and random fields: accuracy, closed and oriented surfaces, topology, counts, determinism.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <unordered_map>
#include <vector>

#include <doctest/doctest.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "volume/marching_cubes.h"

using namespace facet;

namespace {

constexpr double kPi = std::numbers::pi;

// A volume of `size` samples `spacing` apart, sample (i, j, k) = field((i, j, k)·spacing).
template <typename Field>
Volume sampled(glm::ivec3 size, glm::vec3 spacing, const Field& field) {
  Volume volume;
  volume.source = "test field";
  volume.size = size;
  volume.spacing = spacing;
  volume.values.resize(volume.sampleCount());
  for (int z = 0; z < size.z; ++z)
    for (int y = 0; y < size.y; ++y)
      for (int x = 0; x < size.x; ++x)
        volume.values[volume.index(x, y, z)] = static_cast<float>(field(glm::dvec3(x, y, z) * glm::dvec3(spacing)));
  const auto [low, high] = std::minmax_element(volume.values.begin(), volume.values.end());
  volume.minValue = *low;
  volume.maxValue = *high;
  return volume;
}

// Inside a sphere of radius r: r − |p − c|, the signed distance (positive inside).
Volume sphereVolume(glm::ivec3 size, glm::vec3 spacing, glm::dvec3 center, double r) {
  return sampled(size, spacing, [&](glm::dvec3 p) { return r - glm::length(p - center); });
}

// Uniform noise in [0, 1) from a seeded generator, with the border samples
// set to 0 (below any iso in (0, 1)), so that the surface is closed.
// Below `quantum` > 0, values are rounded to multiples of it, so that many
// equal iso exactly.
Volume noiseVolume(int n, std::uint32_t seed, float quantum = 0.0f) {
  std::mt19937 random(seed);
  Volume volume = sampled({n, n, n}, glm::vec3(1.0f), [](glm::dvec3) { return 0.0; });
  for (int z = 1; z + 1 < n; ++z)
    for (int y = 1; y + 1 < n; ++y)
      for (int x = 1; x + 1 < n; ++x) {
        float value = static_cast<float>(random() >> 8) * 0x1p-24f;
        if (quantum > 0.0f) value = std::round(value / quantum) * quantum;
        volume.values[volume.index(x, y, z)] = value;
      }
  volume.maxValue = 1.0f;
  return volume;
}

// Faces of the grid whose inside corners (≥ iso) lie on one diagonal and
// outside ones on the other: where a case table has to choose.
int ambiguousFaces(const Volume& v, float iso) {
  const auto in = [&](int x, int y, int z) { return v.at(x, y, z) >= iso; };
  int count = 0;
  for (int z = 0; z < v.size.z; ++z)
    for (int y = 0; y < v.size.y; ++y)
      for (int x = 0; x < v.size.x; ++x) {
        const bool a = in(x, y, z);
        if (x + 1 < v.size.x && y + 1 < v.size.y)
          count += a == in(x + 1, y + 1, z) && a != in(x + 1, y, z) && a != in(x, y + 1, z);
        if (y + 1 < v.size.y && z + 1 < v.size.z)
          count += a == in(x, y + 1, z + 1) && a != in(x, y + 1, z) && a != in(x, y, z + 1);
        if (x + 1 < v.size.x && z + 1 < v.size.z)
          count += a == in(x + 1, y, z + 1) && a != in(x + 1, y, z) && a != in(x, y, z + 1);
      }
  return count;
}

struct Topology {
  std::size_t unmatchedEdges = 0;     // directed edges used other than once, or whose reverse is not used once
  std::size_t degenerateIndices = 0;  // triangles naming one vertex twice
  std::size_t unusedVertices = 0;
  long long euler = 0;                // V − E + F
};

// Watertight and consistently oriented: every directed edge (a, b) of a
// triangle appears once, and (b, a) once, so every undirected edge is shared
// by exactly two triangles that run along it in opposite directions.
Topology topology(const Mesh& mesh) {
  Topology result;
  std::unordered_map<std::uint64_t, int> directed;
  std::vector<char> used(mesh.positions.size());
  const auto key = [](std::uint32_t a, std::uint32_t b) { return std::uint64_t{a} << 32 | b; };
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const std::uint32_t v[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) ++result.degenerateIndices;
    for (int e = 0; e < 3; ++e) {
      ++directed[key(v[e], v[(e + 1) % 3])];
      used[v[e]] = 1;
    }
  }
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find(key(static_cast<std::uint32_t>(edge), static_cast<std::uint32_t>(edge >> 32)));
    if (count != 1 || reverse == directed.end() || reverse->second != 1) ++result.unmatchedEdges;
  }
  result.unusedVertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
  result.euler = static_cast<long long>(mesh.positions.size()) - static_cast<long long>(directed.size() / 2) +
                 static_cast<long long>(mesh.triangleCount());
  return result;
}

void checkClosed(const Mesh& mesh) {
  REQUIRE(mesh.indices.size() % 3 == 0);
  REQUIRE(mesh.normals.size() == mesh.positions.size());
  for (std::uint32_t index : mesh.indices) REQUIRE(index < mesh.positions.size());
  const Topology t = topology(mesh);
  CHECK(t.unmatchedEdges == 0);
  CHECK(t.degenerateIndices == 0);
  CHECK(t.unusedVertices == 0);
}

// Finite positions and unit normals.
void checkFinite(const Mesh& mesh) {
  int bad = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) ++bad;
    if (!(std::fabs(glm::length(n) - 1.0f) < 1e-5f)) ++bad;
  }
  CHECK(bad == 0);
}

double area(const Mesh& mesh) {
  double sum = 0.0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]], c = mesh.positions[mesh.indices[t + 2]];
    sum += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  return sum;
}

// Σ a·(b × c)/6 over the triangles: the enclosed volume of a closed mesh,
// positive when its triangles turn counter-clockwise seen from outside.
double signedVolume(const Mesh& mesh) {
  double sum = 0.0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]], c = mesh.positions[mesh.indices[t + 2]];
    sum += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return sum;
}

bool same(const Mesh& a, const Mesh& b) {
  return a.positions == b.positions && a.normals == b.normals && a.indices == b.indices;
}

// The sphere of radius 0.35 in the unit box, its centre off the grid, at
// about 32 samples along each axis, isotropic or not.
struct SphereCase {
  glm::vec3 spacing;
  glm::ivec3 size;
  glm::dvec3 center{0.5 + 0.0123, 0.5 - 0.0071, 0.5 + 0.0047};
  double r = 0.35;
  double longestEdge() const { return std::max({spacing.x, spacing.y, spacing.z}); }
};

std::vector<SphereCase> sphereCases() {
  const float h = 1.0f / 31.0f;
  return {{glm::vec3(h), glm::ivec3(32)}, {glm::vec3(h, 1.5f * h, 0.75f * h), glm::ivec3(32, 22, 42)}};
}

}  // namespace

TEST_CASE("marching cubes: a sphere's vertices, normals, area and volume") {
  for (const SphereCase& sphere : sphereCases()) {
    CAPTURE(sphere.spacing);
    const Mesh mesh = marchingCubes(sphereVolume(sphere.size, sphere.spacing, sphere.center, sphere.r), 0.0f);
    CHECK(mesh.name == "isosurface");
    REQUIRE(mesh.triangleCount() > 1000);
    checkFinite(mesh);

    // f = r − |p − c| is the signed distance, so a vertex's distance from
    // the sphere is |f| there, and f is concave along any line (|p − c| is
    // convex): the chord between two samples lies below f, so its zero
    // (the vertex) has f ≥ 0 and lies inside. Linear interpolation over an
    // edge of length h is off by at most h²/8·max|f''|, and along a line
    // |f''| ≤ 1/ρ at distance ρ from c, where ρ ≥ r − h on a crossed edge:
    // 0 ≤ f(vertex) ≤ h²/(8(r − h)) (4.1e-4 at h = 1/31, 9.6e-4 at 1.5/31).
    // Measured: 3.7e-4 and 8.4e-4, on edges nearly tangent to the sphere.
    const double h = sphere.longestEdge();
    const double bound = h * h / (8.0 * (sphere.r - h));
    double deepest = 0.0, outside = 0.0;
    for (const glm::vec3& p : mesh.positions) {
      const double f = sphere.r - glm::length(glm::dvec3(p) - sphere.center);
      deepest = std::max(deepest, f);
      outside = std::max(outside, -f);
    }
    CAPTURE(deepest);
    CAPTURE(bound);
    CHECK(outside < 1e-6);  // float rounding of the samples and the positions only
    CHECK(deepest <= bound + 1e-6);

    // Normals: central differences of the distance err by O(h²/r²) rad
    // (the third derivative of |p| is ~1/r²), and interpolating between the
    // radial directions at two samples h apart by O((h/r)²) too:
    // (h/r)² = 0.49° at h = 1/31, 1.1° at 1.5/31. Measured: 0.11° and 0.28°.
    double worst = 0.0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const glm::dvec3 radial = glm::normalize(glm::dvec3(mesh.positions[v]) - sphere.center);
      const double cosine = std::clamp(glm::dot(radial, glm::dvec3(mesh.normals[v])), -1.0, 1.0);
      worst = std::max(worst, std::acos(cosine) * 180.0 / kPi);
    }
    CAPTURE(worst);
    const double secondOrder = (h / sphere.r) * (h / sphere.r);
    CHECK(worst < secondOrder * 180.0 / kPi);

    // Area and volume: a piecewise linear surface through points within
    // O(h²/r) of a sphere is off by O((h/r)²) relative in both (0.85% at
    // h = 1/31, 1.9% at 1.5/31). The triangles are convex combinations of
    // vertices inside the ball, so the volume can only fall short. Measured:
    // −0.27% and −0.33% in area, −0.51% and −0.63% in volume.
    const double sphereArea = 4.0 * kPi * sphere.r * sphere.r, sphereVolume = 4.0 / 3.0 * kPi * std::pow(sphere.r, 3.0);
    const double areaError = area(mesh) / sphereArea - 1.0, volumeError = signedVolume(mesh) / sphereVolume - 1.0;
    CAPTURE(areaError);
    CAPTURE(volumeError);
    CHECK(std::fabs(areaError) < secondOrder);
    CHECK(volumeError < 0.0);
    CHECK(volumeError > -secondOrder);
  }
}

TEST_CASE("marching cubes: the sphere is watertight and oriented, Euler characteristic 2") {
  for (const SphereCase& sphere : sphereCases()) {
    const Mesh mesh = marchingCubes(sphereVolume(sphere.size, sphere.spacing, sphere.center, sphere.r), 0.0f);
    checkClosed(mesh);
    CHECK(topology(mesh).euler == 2);
    CHECK(signedVolume(mesh) > 0.0);
  }
}

TEST_CASE("marching cubes: a torus has Euler characteristic 0") {
  // Inside a torus about the z axis, radii 0.25 (to the tube's centre) and 0.1.
  const Volume torus = sampled(glm::ivec3(40), glm::vec3(1.0f / 39.0f), [](glm::dvec3 p) {
    const glm::dvec3 q = p - glm::dvec3(0.503, 0.497, 0.51);
    return 0.1 - std::hypot(std::hypot(q.x, q.y) - 0.25, q.z);
  });
  const Mesh mesh = marchingCubes(torus, 0.0f);
  checkClosed(mesh);
  checkFinite(mesh);
  CHECK(topology(mesh).euler == 0);
  // 2π²Rr², with the tube's radius only 3.9 samples: measured −1.4%.
  const double volume = 2.0 * kPi * kPi * 0.25 * 0.1 * 0.1;
  CHECK(signedVolume(mesh) == doctest::Approx(volume).epsilon(0.03));
}

TEST_CASE("marching cubes: random fields with ambiguous faces are watertight and oriented") {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    CAPTURE(seed);
    const Volume noise = noiseVolume(24, seed);
    for (float iso : {0.3f, 0.5f, 0.7f}) {
      CAPTURE(iso);
      REQUIRE(ambiguousFaces(noise, iso) > 1000);
      const Mesh mesh = marchingCubes(noise, iso);
      REQUIRE(mesh.triangleCount() > 10000);
      checkClosed(mesh);
      checkFinite(mesh);
      // Closed orientable surfaces: V − E + F = 2·(components − genus), even.
      CHECK(topology(mesh).euler % 2 == 0);
      // Every component wound counter-clockwise seen from outside encloses positive volume.
      CHECK(signedVolume(mesh) > 0.0);
    }
  }
}

TEST_CASE("marching cubes: samples equal to iso count as inside, and the mesh stays closed") {
  // Values on multiples of 1/4, so a fifth of the samples equal iso = 0.5:
  // vertices land on samples (t = 0 or 1), and many triangles (a fifth,
  // measured) have no area; the mesh is closed by its indices all the same.
  const Volume noise = noiseVolume(20, 7, 0.25f);
  const Mesh mesh = marchingCubes(noise, 0.5f);
  REQUIRE(mesh.triangleCount() > 1000);
  checkClosed(mesh);
  checkFinite(mesh);
  CHECK(signedVolume(mesh) > 0.0);

  // One sample equal to iso among samples below it: it is inside, the surface
  // shrinks onto it, six vertices at the sample, the normals still unit vectors.
  Volume point = sampled(glm::ivec3(3), glm::vec3(1.0f), [](glm::dvec3) { return 0.0; });
  point.values[point.index(1, 1, 1)] = 2.0f;
  const Mesh onSample = marchingCubes(point, 2.0f);
  CHECK(onSample.triangleCount() == 8);
  checkClosed(onSample);
  checkFinite(onSample);
  for (const glm::vec3& p : onSample.positions) CHECK(p == glm::vec3(1.0f));
}

TEST_CASE("marching cubes: non-finite samples give finite vertices, flat gradients take the faces' normals") {
  // NaN is never ≥ iso (outside); ±∞ and the largest floats are ordinary
  // inside or outside samples whose differences overflow.
  Volume noise = noiseVolume(16, 5);
  const float specials[] = {std::nanf(""), INFINITY, -INFINITY, 3e38f, -3e38f};
  for (int s = 0; s < 200; ++s)
    noise.values[noise.index(1 + s % 14, 1 + s / 14 % 14, 1 + s * 7 % 14)] = specials[s % 5];
  const Mesh mesh = marchingCubes(noise, 0.5f);
  REQUIRE(mesh.triangleCount() > 1000);
  checkClosed(mesh);
  checkFinite(mesh);
  for (const glm::vec3& p : mesh.positions) {
    CHECK(glm::all(glm::greaterThanEqual(p, glm::vec3(0.0f))));
    CHECK(glm::all(glm::lessThanEqual(p, noise.extent())));
  }

  // Samples 0 1 0 1 0 along x: central differences vanish at x = 1, 2, 3,
  // so the gradient between 1 and 2 and between 2 and 3 is zero and the
  // triangles decide: the normals point from the inside samples (1) to the
  // outside ones (0), +x or −x, as those from the gradient do.
  const Volume stripes = sampled({5, 3, 3}, glm::vec3(1.0f), [](glm::dvec3 p) { return std::fmod(p.x, 2.0); });
  const Mesh sheets = marchingCubes(stripes, 0.5f);
  CHECK(sheets.triangleCount() == 4 * 8);
  checkFinite(sheets);
  for (std::size_t v = 0; v < sheets.positions.size(); ++v) {
    const float x = sheets.positions[v].x;
    CAPTURE(x);
    const float expected = std::fmod(x, 2.0f) == 0.5f ? -1.0f : 1.0f;  // the inside sample is at x + 0.5 or x − 0.5
    CHECK(sheets.normals[v].x == doctest::Approx(expected));
  }
}

TEST_CASE("marching cubes: counts for a cell inside, outside, and a single inside sample") {
  const Volume ones = sampled(glm::ivec3(2), glm::vec3(1.0f), [](glm::dvec3) { return 1.0; });
  CHECK(marchingCubes(ones, 0.5f).triangleCount() == 0);   // fully inside
  CHECK(marchingCubes(ones, 1.0f).triangleCount() == 0);   // inside: ≥ iso
  CHECK(marchingCubes(ones, 1.5f).triangleCount() == 0);   // fully outside
  const Mesh empty = marchingCubes(ones, 2.0f);             // iso beyond the range: an empty mesh
  CHECK(empty.positions.empty());
  CHECK(empty.indices.empty());

  // One inside sample among 3³: one triangle in each of its 8 cells, a
  // vertex halfway along each of its 6 edges: an octahedron.
  Volume point = sampled(glm::ivec3(3), glm::vec3(1.0f, 2.0f, 0.5f), [](glm::dvec3) { return 0.0; });
  point.values[point.index(1, 1, 1)] = 1.0f;
  const Mesh octahedron = marchingCubes(point, 0.5f);
  CHECK(octahedron.triangleCount() == 8);
  CHECK(octahedron.positions.size() == 6);
  checkClosed(octahedron);
  CHECK(topology(octahedron).euler == 2);
  const glm::vec3 center(1.0f, 2.0f, 0.5f);
  for (std::size_t v = 0; v < octahedron.positions.size(); ++v) {
    const glm::vec3 offset = octahedron.positions[v] - center;
    // Halfway to a neighbour along one axis, the normal pointing away from the centre along it.
    const glm::vec3 steps = glm::abs(offset) / (0.5f * point.spacing);
    CHECK(steps.x + steps.y + steps.z == doctest::Approx(1.0f));
    CHECK(std::max({steps.x, steps.y, steps.z}) == doctest::Approx(1.0f));
    CHECK(glm::dot(octahedron.normals[v], glm::normalize(offset)) == doctest::Approx(1.0f));
  }
  // Volume of the octahedron with half-diagonals 0.5, 1, 0.25: (4/3)·0.5·1·0.25.
  CHECK(signedVolume(octahedron) == doctest::Approx(4.0 / 3.0 * 0.5 * 1.0 * 0.25));

  // Its complement, one outside sample among inside ones: the same 8
  // triangles turned the other way, facing the sample, enclosing a negative volume.
  Volume hole = sampled(glm::ivec3(3), glm::vec3(1.0f), [](glm::dvec3) { return 1.0; });
  hole.values[hole.index(1, 1, 1)] = 0.0f;
  const Mesh cavity = marchingCubes(hole, 0.5f);
  CHECK(cavity.triangleCount() == 8);
  checkClosed(cavity);
  CHECK(signedVolume(cavity) == doctest::Approx(-4.0 / 3.0 * 0.5 * 0.5 * 0.5));
}

TEST_CASE("marching cubes: the same mesh every run, whatever the number of threads") {
  // Ranges of at least 16 slabs go to separate threads: 31 slabs are one
  // range, 32 (one more slice, all outside) are two where the machine has
  // two cores, split at slab 16 through the middle of the surface. The
  // surface stays two slices clear of the top, so the extra slice changes
  // no sample, edge or gradient the mesh uses: the meshes must be equal.
  const auto stack = [](const Volume& volume, int slices) {
    Volume taller = volume;
    taller.size.z += slices;
    taller.values.resize(taller.sampleCount(), volume.values[0]);
    return taller;
  };
  const Volume sphere = sphereVolume({40, 36, 32}, glm::vec3(1.0f), {19.3, 17.6, 15.4}, 12.0);
  const Mesh once = marchingCubes(sphere, 0.0f);
  CHECK(same(once, marchingCubes(sphere, 0.0f)));
  CHECK(same(once, marchingCubes(stack(sphere, 1), 0.0f)));
  CHECK(same(once, marchingCubes(stack(sphere, 40), 0.0f)));

  Volume noise = noiseVolume(32, 11);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) noise.values[noise.index(x, y, 30)] = 0.0f;  // two outside slices on top
  const Mesh random = marchingCubes(noise, 0.5f);
  CHECK(same(random, marchingCubes(noise, 0.5f)));
  CHECK(same(random, marchingCubes(stack(noise, 1), 0.5f)));
  CHECK(same(random, marchingCubes(stack(noise, 90), 0.5f)));
}
