// The coverage of one chosen triangle (pipeline/triangle_coverage.h): the
// same pixel centres from both backends, every pixel the full frame keeps
// for that triangle among them, and the rest hidden by nearer surfaces.
#include <algorithm>

#include <doctest/doctest.h>

#include "cpu/cpu_renderer.h"
#include "gl/gl_renderer.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/triangle_coverage.h"
#include "scene/default_scene.h"

using namespace facet;

TEST_CASE("one triangle's coverage: both backends cover the same pixel centres, and the frame keeps the triangle only among them") {
  const Scene scene = makeDefaultScene();
  RenderSettings settings;
  settings.width = 160;
  settings.height = 120;
  settings.shadows.enabled = false;
  const FrameInputs frame = buildFrameInputs(scene, settings);
  const std::unique_ptr<Renderer> gl = makeGlRenderer(GlContextKind::OsMesa), cpu = makeCpuRenderer(2);
  const std::vector<std::uint32_t> kept = *cpu->render(scene, frame, {FrameOutput::TriangleIds}).triangleIds;
  CHECK(*gl->render(scene, frame, {FrameOutput::TriangleIds}).triangleIds == kept);
  // Triangles the frame shows, each with some pixels: the ground's (large, partly hidden) and small ones of the objects.
  std::vector<std::uint32_t> chosen;
  for (std::size_t pixel = 0; pixel < kept.size() && chosen.size() < 12; pixel += 977)
    if (kept[pixel] != 0 && std::find(chosen.begin(), chosen.end(), kept[pixel]) == chosen.end()) chosen.push_back(kept[pixel]);
  REQUIRE(chosen.size() >= 8);
  int hiddenSomewhere = 0;
  for (const std::uint32_t triangle : chosen) {
    CAPTURE(triangle);
    const SingleTriangle single = singleTriangle(scene, frame, triangle);
    const std::vector<std::uint32_t> counts = *cpu->render(single.scene, single.frame, {FrameOutput::FragmentCounts}).fragmentCounts;
    CHECK(*gl->render(single.scene, single.frame, {FrameOutput::FragmentCounts}).fragmentCounts == counts);
    int covered = 0, keptHere = 0, keptOutside = 0;
    for (std::size_t pixel = 0; pixel < counts.size(); ++pixel) {
      CHECK(counts[pixel] <= 1);  // one triangle: one fragment at most
      covered += counts[pixel] != 0;
      keptHere += counts[pixel] != 0 && kept[pixel] == triangle;
      keptOutside += counts[pixel] == 0 && kept[pixel] == triangle;
    }
    CHECK(keptHere > 0);
    CHECK(keptOutside == 0);
    hiddenSomewhere += covered > keptHere;
  }
  // And one the objects hide in part: searched among every triangle the frame shows.
  std::vector<std::uint32_t> shown(kept);
  std::sort(shown.begin(), shown.end());
  shown.erase(std::unique(shown.begin(), shown.end()), shown.end());
  for (std::size_t i = 1; i < shown.size() && hiddenSomewhere == 0; ++i) {
    const SingleTriangle single = singleTriangle(scene, frame, shown[i]);
    const std::vector<std::uint32_t> counts = *cpu->render(single.scene, single.frame, {FrameOutput::FragmentCounts}).fragmentCounts;
    int covered = 0, keptHere = 0;
    for (std::size_t pixel = 0; pixel < counts.size(); ++pixel) covered += counts[pixel] != 0, keptHere += counts[pixel] != 0 && kept[pixel] == shown[i];
    if (covered > keptHere) {
      ++hiddenSomewhere;
      CHECK(*gl->render(single.scene, single.frame, {FrameOutput::FragmentCounts}).fragmentCounts == counts);
    }
  }
  CHECK(hiddenSomewhere > 0);
  CHECK_THROWS_WITH(singleTriangle(scene, frame, 0), doctest::Contains("numbered from 1"));
}
