// Clipping at the near plane and perspective-correct interpolation.
#include <algorithm>
#include <cmath>

#include <doctest/doctest.h>
#include <glm/trigonometric.hpp>

#include "cpu/clipper.h"
#include "cpu/interpolation.h"
#include "cpu/rasterize.h"
#include "cpu/triangle_setup.h"
#include "cpu_test_scenes.h"
#include "math/projection.h"

using namespace facet;
using namespace facet::cpu;

TEST_CASE("a triangle crossing the near plane is clipped: drawn in front of the eye, not mirrored, not dropped") {
  // A floor triangle running from 5 m ahead of the eye to 5 m behind it.
  Scene scene;
  Mesh floor;
  floor.positions = {{-1, -1, -5}, {1, -1, -5}, {0, -1, 5}};
  floor.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  floor.indices = {0, 1, 2};
  scene.meshes.push_back(floor);
  scene.instances.push_back({0, glm::mat4(1.0f)});
  RenderSettings s = test::topDownSettings(64);
  s.camera.projection = ProjectionKind::Perspective;
  s.camera.eye = {0, 0, 0};
  s.camera.reference = {0, 0, -1};
  s.camera.up = {0, 1, 0};
  s.camera.near = 0.1f;
  s.cullBackFaces = false;
  s.ambient = 1.0f;
  s.material.ka = 1.0f;
  const Image image = test::renderCpu(scene, s);
  int lower = 0, upper = 0, bottomRow = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      if (image.at(x, y).r > 0) (y < 32 ? lower : upper) += 1;
  for (int x = 0; x < 64; ++x) bottomRow += image.at(x, 0).r > 0;
  CHECK(lower > 300);      // drawn: the part in front of the eye fills the lower half's centre
  CHECK(upper == 0);       // a mirrored vertex behind the eye would reach into the upper half
  CHECK(bottomRow > 0);    // it runs down to the near plane, below the bottom of the image
}

TEST_CASE("clipped vertices lie on the clip planes, with attributes interpolated in clip space") {
  ClipVertex a, b, c;
  a.clip = {0, 0, -1, 1};   // behind the near plane (z < 0)
  b.clip = {0.5f, 0, 1, 2};
  c.clip = {-0.5f, 0.5f, 1, 2};
  a.varyings[0] = 0.0f;
  b.varyings[0] = 4.0f;
  c.varyings[0] = 4.0f;
  std::vector<WindowVertex> out;
  clipTriangle(a, b, c, toWindow(a, 8, 8, 1), toWindow(b, 8, 8, 1), toWindow(c, 8, 8, 1), 8, 8, 1, out);
  REQUIRE(out.size() == 6);  // a quad: two fan triangles
  for (const WindowVertex& v : out) {
    CHECK(v.z >= 0.0f);
    CHECK(v.invW > 0.0f);
  }
  // The edge a->b crosses z = 0 at t = 1/2 (z from -1 to 1): w = 1.5, varying 2.
  bool found = false;
  for (const WindowVertex& v : out)
    if (std::fabs(v.z) < 1e-6f && std::fabs(1.0f / v.invW - 1.5f) < 1e-5f) found = std::fabs(v.varyings[0] - 2.0f) < 1e-5f;
  CHECK(found);
}

TEST_CASE("all three vertices outside one plane or NaN: nothing") {
  ClipVertex a, b, c;
  a.clip = {2, 0, 0.5f, 1};
  b.clip = {3, 1, 0.5f, 1};
  c.clip = {2, -1, 0.5f, 1};
  std::vector<WindowVertex> out;
  clipTriangle(a, b, c, toWindow(a, 8, 8, 0), toWindow(b, 8, 8, 0), toWindow(c, 8, 8, 0), 8, 8, 0, out);
  CHECK(out.empty());
  a.clip = {NAN, 0, 0.5f, 1};
  b.clip = {0, 0.5f, 0.5f, 1};
  c.clip = {0.5f, 0, 0.5f, 1};
  clipTriangle(a, b, c, toWindow(a, 8, 8, 0), toWindow(b, 8, 8, 0), toWindow(c, 8, 8, 0), 8, 8, 0, out);
  CHECK(out.empty());
}

TEST_CASE("perspective-correct interpolation across a slanted quad matches the analytic value") {
  // A floor y = -1 from z = 2 to z = 10 (eye space), x in [-1, 1]; the varying is eye z.
  // Perspective θ = 45°, square 64x64: the ray through pixel row py meets the floor at
  // z = -1 / (y_ndc·tanθ) with y_ndc = (py + 0.5)/32 - 1.
  const int size = 64;
  const glm::mat4 pm = perspective(glm::radians(45.0f), 1.0f, 0.5f, 50.0f);
  const glm::vec3 corners[4] = {{-1, -1, 2}, {1, -1, 2}, {1, -1, 10}, {-1, -1, 10}};
  ClipVertex v[4];
  WindowVertex w[4];
  for (int i = 0; i < 4; ++i) {
    v[i].clip = pm * glm::vec4(corners[i], 1.0f);
    v[i].varyings[0] = corners[i].z;
    w[i] = toWindow(v[i], 32, 32, 1);
  }
  double worstCorrect = 0, worstLinear = 0;
  int pixels = 0;
  for (const auto& tri : {std::array{0, 1, 2}, std::array{0, 2, 3}}) {
    SnappedTriangle snapped;
    PixelBox box;
    REQUIRE(snapTriangle({w[tri[0]].x, w[tri[1]].x, w[tri[2]].x}, {w[tri[0]].y, w[tri[1]].y, w[tri[2]].y}, snapped));
    REQUIRE(pixelBox(snapped, 0, 0, size - 1, size - 1, box));
    InterpolationVertex vertices[3];
    for (int k = 0; k < 3; ++k) {
      const WindowVertex& corner = w[tri[static_cast<std::size_t>(k)]];
      vertices[k] = {corner.x, corner.y, corner.z, corner.invW, corner.varyings.data()};
    }
    toSetUpOrder(snapped, vertices);
    Interpolation in(vertices[0], vertices[1], vertices[2]);
    in.setUpVaryings(1);
    rasterize(snapped, box, [&](int px, int py) {
      float varying = 0;
      in.varyingsAt(px, py, &varying);
      const double yNdc = (py + 0.5) / 32.0 - 1.0;
      const double analytic = -1.0 / (yNdc * std::tan(glm::radians(45.0)));
      worstCorrect = std::max(worstCorrect, std::fabs(varying - analytic) / analytic);
      // What screen-linear interpolation would give: the same weights without the 1/w.
      const float x = static_cast<float>(px) + 0.5f, y = static_cast<float>(py) + 0.5f;
      const WindowVertex &a = w[tri[0]], &b = w[tri[1]], &c = w[tri[2]];
      const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
      const float la = ((b.x - x) * (c.y - y) - (c.x - x) * (b.y - y)) / area;
      const float lb = ((c.x - x) * (a.y - y) - (a.x - x) * (c.y - y)) / area;
      const float linear = la * a.varyings[0] + lb * b.varyings[0] + (1 - la - lb) * c.varyings[0];
      worstLinear = std::max(worstLinear, std::fabs(linear - analytic) / analytic);
      ++pixels;
    });
  }
  CHECK(pixels > 100);
  CHECK(worstCorrect < 1e-4);
  CHECK(worstLinear > 0.2);  // the test would catch affine interpolation
}
