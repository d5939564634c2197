// Anti-aliasing (renderer/PIPELINE.md, section 7, "Anti-aliasing"): where
// the samples lie, that a sample's pass sees the image at its offset, that
// an edge pixel takes the fraction of its samples the surface covers, and
// how fast 1, 4, 9 and 16 samples converge to a 16 x 16 supersampled frame
// (printed figures).
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "cpu/cpu_renderer.h"
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
  // A white square, emission only, over black, its right edge 0.3 of the way across pixel column 40.
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

TEST_CASE("anti-aliasing: 1, 4, 9 and 16 samples converge towards a 16 x 16 supersampled frame, grid and jittered") {
  const Scene scene = loadGltf(std::string(FACET_ASSETS) + "/antialiasing.gltf");
  RenderSettings s;
  s.width = 160, s.height = 100;
  const FrameInputs plain = buildFrameInputs(scene, s);
  FrameInputs fine = plain;
  fine.samples = sampleOffsets(16, SamplePattern::Grid, 1);  // 256 samples: beyond the settings' 16, the reference
  const auto renderer = makeCpuRenderer(2);
  const Image reference = renderer->render(scene, fine).image;
  for (const SamplePattern pattern : {SamplePattern::Grid, SamplePattern::Jittered}) {
    double previous = 1e9, single = 0;
    std::printf("anti-aliasing, %s: RMS error (8-bit levels) against 16 x 16 samples on assets/antialiasing.gltf at 160x100:",
                kSamplePatternNames[static_cast<std::size_t>(pattern)].data());
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
    CHECK(previous < 0.25 * single);  // 16 samples: under a quarter of one sample's error (measured 0.21 grid, 0.15 jittered)
  }
}
