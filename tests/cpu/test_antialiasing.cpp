// Anti-aliasing (renderer/PIPELINE.md, "Anti-aliasing"): where
// the samples lie, that a sample's pass sees the image at its offset, that
// an edge pixel takes the fraction of its samples the surface covers, and
// how fast 1, 4, 9 and 16 samples converge to a 16 x 16 supersampled frame
// and to the course's exact area-weighted averaging (printed figures).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "common/error.h"
#include "cpu/area_coverage.h"
#include "cpu/cpu_renderer.h"
#include "cpu/area_averaging.h"
#include "cpu/reference/reference_renderer.h"
#include "cpu_test_scenes.h"
#include "image/srgb.h"
#include "pipeline/antialiasing.h"
#include "pipeline/frame_inputs.h"
#include "scene/gltf_loader.h"

using namespace facet;

namespace {

// (px, py) of world point p in `frame`'s window: PM·EM, divide, viewport.
glm::vec2 windowOf(const FrameInputs& frame, glm::vec3 p) {
  const glm::vec4 clip = frame.clipFromWorld * glm::vec4(p, 1.0f);
  const glm::vec4 window = frame.windowFromNdc * glm::vec4(glm::vec3(clip) / clip.w, 1.0f);
  return {window.x, window.y};
}

// Root-mean-square difference of two images' colour levels.
double rms(const Image& a, const Image& b) {
  double sum = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const Rgba8 p = a.at(x, y), q = b.at(x, y);
      sum += (p.r - q.r) * (p.r - q.r) + (p.g - q.g) * (p.g - q.g) + (p.b - q.b) * (p.b - q.b);
    }
  return std::sqrt(sum / (3.0 * a.width() * a.height()));
}

// A white square, emission only, over black, its right edge 0.3 of the way across pixel column 40 (topDownSettings(64)).
Scene edgeScene() {
  constexpr int kSize = 64;
  Scene scene;
  const int material = scene.addMaterial("white", glm::vec3(0.0f), 0.0f, 1.0f);
  scene.materials[0].emissive = glm::vec3(1.0f);
  Mesh m;
  const float edge = (40.0f + 0.3f) * 4.0f / kSize - 2.0f;  // world x of that edge (topDownSettings: 4 units over 64 pixels)
  for (const glm::vec2 c : {glm::vec2(-1.9f, 1.9f), glm::vec2(edge, 1.9f), glm::vec2(edge, -1.9f), glm::vec2(-1.9f, -1.9f)}) {
    m.positions.push_back({c.x, 0.0f, c.y});
    m.normals.push_back({0, 1, 0});
  }
  m.indices = {0, 1, 2, 0, 2, 3};
  scene.addObject(std::move(m), material, glm::mat4(1.0f));
  return scene;
}

// The maximum and root-mean-square difference of two images' colour levels.
struct Difference {
  int max = 0;
  double rms = 0;
};
Difference differenceOf(const Image& a, const Image& b) {
  Difference d;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const Rgba8 p = a.at(x, y), q = b.at(x, y);
      d.max = std::max({d.max, std::abs(int{p.r} - q.r), std::abs(int{p.g} - q.g), std::abs(int{p.b} - q.b)});
    }
  d.rms = rms(a, b);
  return d;
}

// A triangle of the area rule, flat at depth z, from corners in window coordinates.
cpu::AreaSurface surface(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double z, cpu::AreaRole role = cpu::AreaRole::Opaque) {
  cpu::AreaSurface s;
  s.corner[0] = a, s.corner[1] = b, s.corner[2] = c;
  s.z0 = z;
  s.role = role;
  return s;
}

}  // namespace

TEST_CASE("anti-aliasing: grid samples at the cells' centres, jittered ones one per cell and the same for a seed") {
  const std::vector<glm::vec2> grid = sampleOffsets(2, SamplePattern::Grid, 1);
  CHECK(grid == std::vector<glm::vec2>{{-0.25f, -0.25f}, {0.25f, -0.25f}, {-0.25f, 0.25f}, {0.25f, 0.25f}});
  CHECK(sampleOffsets(3, SamplePattern::Grid, 1)[4] == glm::vec2(0.0f));  // the middle cell's centre
  const std::vector<glm::vec2> a = sampleOffsets(4, SamplePattern::Jittered, 7), b = sampleOffsets(4, SamplePattern::Jittered, 8);
  CHECK(a == sampleOffsets(4, SamplePattern::Jittered, 7));
  CHECK(a != b);
  std::set<std::pair<int, int>> cells;
  for (const glm::vec2 o : a) {
    CHECK((o.x >= -0.5f && o.x < 0.5f && o.y >= -0.5f && o.y < 0.5f));
    cells.insert({static_cast<int>(std::floor((o.x + 0.5f) * 4)), static_cast<int>(std::floor((o.y + 0.5f) * 4))});
  }
  CHECK(cells.size() == 16);  // one in each cell
}

TEST_CASE("anti-aliasing: a sample's pass puts each pixel's centre where its sample lies") {
  const Scene scene = test::groundScene(1, glm::vec3(0.5f));
  const FrameInputs frame = buildFrameInputs(scene, test::topDownSettings(64));
  const glm::vec3 p{0.3f, 0.0f, -0.7f};
  const glm::vec2 offset{0.375f, -0.125f};
  const glm::vec2 moved = windowOf(sampleFrame(frame, offset), p), base = windowOf(frame, p);
  CHECK(moved.x == doctest::Approx(base.x - offset.x).epsilon(1e-5));
  CHECK(moved.y == doctest::Approx(base.y - offset.y).epsilon(1e-5));
}

TEST_CASE("anti-aliasing: an edge pixel is the fraction of its samples the surface covers, averaged in linear light") {
  constexpr int kSize = 64;
  const Scene scene = edgeScene();
  RenderSettings s = test::topDownSettings(kSize);
  s.ambient = 0.0f;
  for (const int samples : {4, 9, 16}) {
    CAPTURE(samples);
    s.antialiasing.samples = samples;
    const Image image = test::renderCpu(scene, s);
    const int side = samplesPerSide(samples);
    int covered = 0;  // columns of samples left of 0.3 of the pixel: (i + 0.5)/s < 0.3
    for (int i = 0; i < side; ++i) covered += (static_cast<float>(i) + 0.5f) / static_cast<float>(side) < 0.3f ? 1 : 0;
    const float fraction = static_cast<float>(covered) / static_cast<float>(side);
    CHECK(image.at(40, 20) == test::expectedPixel(glm::vec3(fraction)));
    CHECK(image.at(39, 20) == test::expectedPixel(glm::vec3(1.0f)));
    CHECK(image.at(41, 20) == test::expectedPixel(glm::vec3(0.0f)));
  }
}

TEST_CASE("anti-aliasing, area: a pixel's cells are the exact parts each surface shows, front to back") {
  using cpu::AreaCell;
  using cpu::AreaRole;
  // The visible area of each surface in pixel (px, py): the cells whose front surface it is (-1: the background).
  const auto visibleAreas = [](const std::vector<cpu::AreaSurface>& surfaces, int px, int py) {
    std::vector<std::uint32_t> all(surfaces.size());
    for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    std::vector<AreaCell> cells;
    std::vector<std::uint32_t> fragments;
    cpu::pixelCells(surfaces, all, px, py, cells, fragments);
    std::vector<double> area(surfaces.size() + 1, 0.0);  // [surfaces.size()]: the background
    double total = 0;
    for (const AreaCell& c : cells) {
      area[c.count ? fragments[c.first] : surfaces.size()] += c.area;
      total += c.area;
    }
    CHECK(total == doctest::Approx(1.0).epsilon(1e-12));
    return area;
  };
  SUBCASE("a lone triangle: the part of the square under its edge") {
    const cpu::AreaSurface big = surface({0, 0}, {2, 0}, {0, 2}, 0.5);
    CHECK(cpu::coveredArea(big, 0, 0) == doctest::Approx(1.0));
    CHECK(cpu::coveredArea(big, 1, 0) == doctest::Approx(0.5));
    CHECK(cpu::coveredArea(big, 1, 1) == doctest::Approx(0.0));
    CHECK(cpu::coveredArea(surface({0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, 0.5), 0, 0) == doctest::Approx(0.125));
  }
  SUBCASE("two triangles sharing the diagonal: half each, nothing twice, nothing left") {
    const std::vector<double> area = visibleAreas({surface({0, 0}, {1, 0}, {0, 1}, 0.5), surface({1, 0}, {1, 1}, {0, 1}, 0.5)}, 0, 0);
    CHECK(area[0] == doctest::Approx(0.5));
    CHECK(area[1] == doctest::Approx(0.5));
    CHECK(area[2] == doctest::Approx(0.0).epsilon(1e-12));
  }
  SUBCASE("intersecting surfaces: each in front where its depth is the smaller") {
    cpu::AreaSurface tilted = surface({-1, -1}, {4, -1}, {-1, 4}, 0.0);
    tilted.dzdx = 0.1;  // z = 0.1·(x - 0.3) + 0.5: nearer than 0.5 left of x = 0.3
    tilted.z0 = 0.5 - 0.03;
    const std::vector<double> area = visibleAreas({surface({-1, -1}, {4, -1}, {-1, 4}, 0.5), tilted}, 0, 0);
    CHECK(area[1] == doctest::Approx(0.3));
    CHECK(area[0] == doctest::Approx(0.7));
  }
  SUBCASE("equal depths: the earlier drawn stays in front, as the z-buffer's LESS keeps it") {
    const std::vector<double> area = visibleAreas({surface({-1, -1}, {4, -1}, {-1, 4}, 0.5), surface({-1, -1}, {4, -1}, {-1, 4}, 0.5)}, 0, 0);
    CHECK(area[0] == doctest::Approx(1.0));
  }
  SUBCASE("a blended surface lists before the opaque one it lies over; one behind is gone") {
    std::vector<AreaCell> cells;
    std::vector<std::uint32_t> fragments;
    const std::vector<cpu::AreaSurface> surfaces = {surface({-1, -1}, {4, -1}, {-1, 4}, 0.5),
                                                   surface({0, 0}, {1, 0}, {0, 1}, 0.2, AreaRole::Blended),
                                                   surface({-1, -1}, {4, -1}, {-1, 4}, 0.9, AreaRole::Blended)};
    cpu::pixelCells(surfaces, {0, 1, 2}, 0, 0, cells, fragments);
    double over = 0, plain = 0;
    for (const AreaCell& c : cells) {
      const std::vector<std::uint32_t> list(fragments.begin() + c.first, fragments.begin() + c.first + c.count);
      if (list == std::vector<std::uint32_t>{1, 0}) over += c.area;
      else if (list == std::vector<std::uint32_t>{0}) plain += c.area;
      else FAIL("unexpected list");
    }
    CHECK(over == doctest::Approx(0.5));
    CHECK(plain == doctest::Approx(0.5));
  }
  SUBCASE("a pixel cut into more cells than the limit is refused, naming it") {
    std::vector<cpu::AreaSurface> fan;  // kMaxAreaCells + 1 wedges around the centre of pixel (3, 5)
    const int n = static_cast<int>(kMaxAreaCells) + 1;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * 3.141592653589793 * k / n, b = 2 * 3.141592653589793 * (k + 1) / n;
      fan.push_back(surface({3.5, 5.5}, {3.5 + 0.4 * std::cos(a), 5.5 + 0.4 * std::sin(a)}, {3.5 + 0.4 * std::cos(b), 5.5 + 0.4 * std::sin(b)}, 0.5));
    }
    std::vector<std::uint32_t> all(fan.size());
    for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    std::vector<AreaCell> cells;
    std::vector<std::uint32_t> fragments;
    CHECK_THROWS_WITH_AS(cpu::pixelCells(fan, all, 3, 5, cells, fragments), doctest::Contains("pixel (3, 5) is cut into more than 4096 cells"), Error);
  }
}

TEST_CASE("anti-aliasing, area: each cell is shaded at its centroid, as a sample there would be") {
  // One triangle over the left 0.3 of pixel (0, 0) of a 2 x 1 frame, its one varying the window x: the
  // pixel sums area × the x of the covered part's centroid (half its width), not of the pixel's centre.
  const float x[3] = {0.3f, 0.3f, -20.0f}, y[3] = {-10.0f, 10.0f, 0.0f};
  cpu::SnappedTriangle snapped;
  REQUIRE(cpu::snapTriangle(x, y, snapped));
  cpu::InterpolationVertex v[3] = {{x[0], y[0], 0.5f, 1.0f, &x[0]}, {x[1], y[1], 0.5f, 1.0f, &x[1]}, {x[2], y[2], 0.5f, 1.0f, &x[2]}};
  cpu::toSetUpOrder(snapped, v);
  cpu::Interpolation planes(v[0], v[1], v[2]);
  planes.setUpVaryings(1);
  cpu::AreaAveraging area(2, 1);
  area.collect(snapped, planes, cpu::AreaRole::Opaque, false);
  area.cut();
  area.shade(planes, [](const cpu::Interpolation& moved, int px, int py) -> std::optional<glm::vec4> {
    return glm::vec4(moved.varyingAt(0, px, py), 0.0f, 0.0f, 1.0f);
  });
  FrameInputs frame;
  frame.width = 2, frame.height = 1;
  const ColorBuffer sum = area.composite(frame);
  const double covered = std::nearbyint((0.3 - 0.5) * 256.0) / 256.0 + 0.5;  // the edge on the 1/256 grid
  CHECK(sum.at(0, 0).r == doctest::Approx(covered * (covered / 2)).epsilon(1e-5));
  CHECK(sum.at(0, 0).a == doctest::Approx(1.0));
  CHECK(sum.at(1, 0) == glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));  // the background, whole
}

TEST_CASE("anti-aliasing, area: an edge pixel is the exact fraction of its square the surface covers") {
  constexpr int kSize = 64;
  RenderSettings s = test::topDownSettings(kSize);
  s.ambient = 0.0f;
  s.antialiasing.pattern = SamplePattern::Area;
  s.antialiasing.samples = 4;  // plays no part
  const Image image = test::renderCpu(edgeScene(), s);
  // The edge at window x = 40.3, snapped to the 1/256 grid as the rasterizer snaps it.
  const double fraction = (std::nearbyint((40.3 - 0.5) * 256.0) / 256.0 + 0.5) - 40.0;
  CHECK(image.at(40, 20) == test::expectedPixel(glm::vec3(static_cast<float>(fraction))));
  CHECK(image.at(39, 20) == test::expectedPixel(glm::vec3(1.0f)));
  CHECK(image.at(41, 20) == test::expectedPixel(glm::vec3(0.0f)));
  s.antialiasing.pattern = SamplePattern::Grid;
  s.antialiasing.samples = 1;
  CHECK(test::renderCpu(edgeScene(), s).at(40, 20) == test::expectedPixel(glm::vec3(0.0f)));  // one sample: the centre is outside
}

TEST_CASE("anti-aliasing, area: what it does not cover is refused, naming the key") {
  RenderSettings s;
  s.width = 64, s.height = 48;
  s.antialiasing.pattern = SamplePattern::Area;
  const auto renderer = makeCpuRenderer(1);
  const Scene lines = loadGltf(std::string(FACET_ASSETS) + "/scenes/lines_points.gltf");
  CHECK_THROWS_WITH_AS(renderer->render(lines, buildFrameInputs(lines, s)), doctest::Contains("settings key 'antialiasing.pattern': area covers triangles only"), Error);
  const Scene painter = loadGltf(std::string(FACET_ASSETS) + "/painter.gltf");
  s.hsr = HiddenSurface::Painter;
  CHECK_THROWS_WITH_AS(renderer->render(painter, buildFrameInputs(painter, s)), doctest::Contains("settings key 'hsr'"), Error);
}

TEST_CASE("anti-aliasing, area: blended surfaces over opaque ones agree with 16 x 16 samples") {
  // The cells composite blended surfaces over the opaque one in front, as each sample's pass does. Shadows
  // off: a shadow is shading, taken once per cell at its centroid, where 256 samples average it.
  const Scene scene = loadGltf(std::string(FACET_ASSETS) + "/transparency.gltf");
  RenderSettings s;
  s.width = 120, s.height = 90;
  s.shadows.enabled = false;
  FrameInputs fine = buildFrameInputs(scene, s);
  fine.samples = sampleOffsets(16, SamplePattern::Grid, 1);
  const auto renderer = makeCpuRenderer(2);
  const Image sampled = renderer->render(scene, fine).image;
  s.antialiasing.pattern = SamplePattern::Area;
  const Difference d = differenceOf(renderer->render(scene, buildFrameInputs(scene, s)).image, sampled);
  std::printf("anti-aliasing, area against 16 x 16 grid samples on assets/transparency.gltf at 120x90, shadows off: RMS %.2f, max %d levels\n", d.rms, d.max);
  // Measured 0.22 and 4: a 16 x 16 grid places an edge to 1/32 of a pixel, up to 4 levels of a 1/255 step.
  CHECK(d.rms < 0.5);
  CHECK(d.max <= 8);
}

TEST_CASE("anti-aliasing, area: a masked surface hides what is behind it only where its mask keeps it") {
  // A grey ground seen from above, and over it a white quad of a masked material.
  Scene scene = test::groundScene(1, glm::vec3(0.3f));
  const int material = scene.addMaterial("masked", glm::vec3(1.0f), 0.0f, 1.0f);
  scene.materials[static_cast<std::size_t>(material)].alphaMode = AlphaMode::Mask;
  Mesh quad;
  for (const glm::vec2 c : {glm::vec2(-1.03f, 1.01f), glm::vec2(0.97f, 1.01f), glm::vec2(0.97f, -0.99f), glm::vec2(-1.03f, -0.99f)}) {
    quad.positions.push_back({c.x, 0.5f, c.y});
    quad.normals.push_back({0, 1, 0});
  }
  quad.indices = {0, 1, 2, 0, 2, 3};
  RenderSettings s = test::topDownSettings(40);
  s.antialiasing.pattern = SamplePattern::Area;
  const Image ground = test::renderCpu(scene, s);
  scene.addObject(std::move(quad), material, glm::mat4(1.0f));
  SUBCASE("an α under the cutoff: nothing of it shows") {
    scene.materials[static_cast<std::size_t>(material)].baseColor.a = 0.2f;
    CHECK(test::renderCpu(scene, s) == ground);
  }
  SUBCASE("an α over the cutoff: it shows as an opaque surface does, edges averaged") {
    scene.materials[static_cast<std::size_t>(material)].baseColor.a = 0.8f;
    const Image masked = test::renderCpu(scene, s);
    scene.materials[static_cast<std::size_t>(material)].alphaMode = AlphaMode::Opaque;
    CHECK(masked == test::renderCpu(scene, s));
    CHECK(masked != ground);
  }
}

TEST_CASE("anti-aliasing: 1, 4, 9 and 16 samples converge towards area-weighted averaging and a 16 x 16 supersampled frame") {
  const Scene scene = loadGltf(std::string(FACET_ASSETS) + "/antialiasing.gltf");
  RenderSettings s;
  s.width = 160, s.height = 100;
  s.shadows.enabled = false;  // shadows are shading, taken once per cell by the area rule: the edges here are the polygons'
  FrameInputs fine = buildFrameInputs(scene, s);
  fine.samples = sampleOffsets(16, SamplePattern::Grid, 1);  // 256 samples: beyond the settings' 16
  const auto renderer = makeCpuRenderer(2);
  const Image supersampled = renderer->render(scene, fine).image;
  s.antialiasing.pattern = SamplePattern::Area;
  const Image area = renderer->render(scene, buildFrameInputs(scene, s)).image;
  // The exact coverage and 256 samples differ by the samples' own coverage error (an edge placed to 1/32 of a
  // pixel) and the cells' centroid shading: measured RMS 1.16, max 10 levels, nearly all on the far tiles.
  const Difference between = differenceOf(area, supersampled);
  std::printf("anti-aliasing on assets/antialiasing.gltf at 160x100, shadows off: area-weighted averaging against 16 x 16 samples: RMS %.2f, max %d levels\n",
              between.rms, between.max);
  CHECK(between.rms < 1.5);
  CHECK(between.max <= 16);
  for (const auto& [reference, name] : {std::pair<const Image&, const char*>{area, "area-weighted averaging"}, {supersampled, "16 x 16 samples"}})
    for (const SamplePattern pattern : {SamplePattern::Grid, SamplePattern::Jittered}) {
      double previous = 1e9, single = 0;
      std::printf("  %s: RMS error (8-bit levels) against %s:", kSamplePatternNames[static_cast<std::size_t>(pattern)].data(), name);
      for (const int samples : {1, 4, 9, 16}) {
        s.antialiasing.samples = samples;
        s.antialiasing.pattern = pattern;
        const double error = rms(renderer->render(scene, buildFrameInputs(scene, s)).image, reference);
        std::printf(" %d: %.2f", samples, error);
        CHECK(error < previous);  // more samples, closer
        previous = error;
        if (samples == 1) single = error;
      }
      std::printf("\n");
      CHECK(previous < 0.25 * single);  // 16 samples: under a quarter of one sample's error
    }
}
