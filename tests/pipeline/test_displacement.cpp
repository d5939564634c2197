// Displacement mapping (renderer/PIPELINE.md, "Textures"): midpoint
// subdivision that shares each edge's new vertex, P' = P + (s·h)·N, normals
// from the displaced surface, and the height map's own checks.
#include <algorithm>
#include <cmath>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "common/error.h"
#include "image/png.h"
#include "pipeline/displacement.h"
#include "scratch_folder.h"

using namespace facet;

namespace {

// A unit quad in the xz plane facing +y, two triangles, texture coordinates over [0, 1]².
Scene quadScene() {
  Scene scene;
  Mesh quad;
  quad.name = "quad";
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, -1}, {0, 0, -1}};
  quad.normals.assign(4, {0, 1, 0});
  quad.texcoords = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  scene.addObject(quad, -1, glm::mat4(1.0f));
  return scene;
}

Image grey(int w, int h, std::uint8_t level) { return Image(w, h, {level, level, level, 255}); }

}  // namespace

TEST_CASE("displacement subdivides by shared edge midpoints and moves each vertex by scale times height along its normal") {
  Scene scene = quadScene();
  displaceMeshes(scene, grey(4, 4, 255), 0.25f, 2);
  const Mesh& m = scene.meshes[0];
  CHECK(m.triangleCount() == 2 * 16);
  // A 2-triangle quad: 5 edges; one subdivision adds 5 vertices (9), the next 16 (25): no edge split twice.
  CHECK(m.positions.size() == 25);
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    CHECK(m.positions[v].y == doctest::Approx(0.25f));  // h = 1 everywhere: the whole quad lifted by s
    CHECK(m.normals[v].y == doctest::Approx(1.0f));     // still flat: the recomputed normals point up
  }
  // Half grey: h = 128/255.
  Scene half = quadScene();
  displaceMeshes(half, grey(2, 2, 128), 1.0f, 0);
  CHECK(half.meshes[0].positions[0].y == doctest::Approx(128.0f / 255.0f));
}

TEST_CASE("the height is read bilinearly at the texture coordinates, t = 0 at the top, REPEAT beyond") {
  Image ramp(2, 1);
  ramp.at(0, 0) = {0, 0, 0, 255}, ramp.at(1, 0) = {255, 255, 255, 255};
  CHECK(heightAt(ramp, 0.25, 0.5) == doctest::Approx(0.0));
  CHECK(heightAt(ramp, 0.75, 0.5) == doctest::Approx(1.0));
  CHECK(heightAt(ramp, 0.5, 0.5) == doctest::Approx(0.5));
  CHECK(heightAt(ramp, 1.25, 0.5) == doctest::Approx(0.0));  // REPEAT
  Image rows(1, 2);  // bottom row first in memory: the top of the image is white
  rows.at(0, 0) = {0, 0, 0, 255}, rows.at(0, 1) = {255, 255, 255, 255};
  CHECK(heightAt(rows, 0.5, 0.25) == doctest::Approx(1.0));
  // A bump in the middle of the quad: the middle vertex rises, the corners stay, the normals tilt.
  Image bump(3, 3, {0, 0, 0, 255});
  bump.at(1, 1) = {255, 255, 255, 255};
  Scene scene = quadScene();
  displaceMeshes(scene, bump, 1.0f, 1);
  const Mesh& m = scene.meshes[0];
  float highest = 0.0f;
  for (const glm::vec3& p : m.positions) highest = std::max(highest, p.y);
  CHECK(highest > 0.3f);
  CHECK(m.positions[0].y < 0.05f);
  bool tilted = false;
  for (const glm::vec3& n : m.normals) tilted = tilted || n.y < 0.95f;
  CHECK(tilted);
}

TEST_CASE("a height map must be greyscale, and a mesh without texture coordinates is left as it is, with a warning") {
  const auto folder = test::scratchFolder("displacement", "greyscale");
  Image colour(2, 2, {10, 10, 10, 255});
  colour.at(1, 0) = {10, 20, 10, 255};
  writePng((folder / "colour.png").string(), colour);
  CHECK_THROWS_WITH_AS(loadHeightMap((folder / "colour.png").string()),
                       doctest::Contains("colour.png: not a greyscale height map: pixel (1, 1) from the top left is (10, 20, 10)"), Error);
  writePng((folder / "grey.png").string(), grey(2, 2, 7));
  CHECK(loadHeightMap((folder / "grey.png").string()).at(0, 0).g == 7);
  Scene scene = quadScene();
  scene.meshes[0].texcoords.clear();
  displaceMeshes(scene, grey(2, 2, 255), 1.0f, 2);
  CHECK(scene.meshes[0].triangleCount() == 2);
  REQUIRE(scene.warnings.size() == 1);
  CHECK(scene.warnings[0] == "meshes[0] 'quad': no TEXCOORD_0 to read the height map at; not displaced");
}
