// Lines and points (renderer/PIPELINE.md, "Lines and points"):
// the CPU backend's segments and points (renderer/cpu/line_raster.cpp,
// line_pass.cpp; the reference renderer's too) against what llvmpipe draws for GL_LINES and GL_POINTS,
// byte for byte: random segments and points in perspective (many clipped by
// the near plane and the sides, in front of and behind a triangle), and in a
// parallel view whose units are pixels, with ends on pixel centres, edges and
// corners, where the diamond-exit rule decides each end pixel.
#include <cstddef>
#include <random>
#include <string>

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "cpu/cpu_renderer.h"
#include "cpu/reference/reference_renderer.h"
#include "gl_test_support.h"
#include "pipeline/frame_inputs.h"
#include "scene/primitives.h"

using namespace facet;

namespace {

// Segments and points with random colours, and a unit square at z = 0 between them.
Scene lineScene(std::mt19937& random, float extent, bool onHalfPixels, std::size_t segments, std::size_t points) {
  std::uniform_real_distribution<float> coordinate(-extent, extent), channel(0.0f, 1.0f);
  const auto position = [&] {
    glm::vec3 p(coordinate(random), coordinate(random), coordinate(random));
    if (onHalfPixels) p = glm::vec3(glm::round(glm::vec2(p) * 4.0f) / 4.0f, p.z);  // quarter pixels: centres, edges, corners
    return p;
  };
  Scene scene;
  Mesh lines, dots;
  lines.name = "segments", dots.name = "points";
  for (std::size_t i = 0; i < 2 * segments; ++i) {
    lines.positions.push_back(position());
    lines.colors.emplace_back(channel(random), channel(random), channel(random), 1.0f);
    lines.lines.push_back(static_cast<std::uint32_t>(i));
  }
  for (std::size_t i = 0; i < points; ++i) {
    dots.positions.push_back(position());
    dots.points.push_back(static_cast<std::uint32_t>(i));
  }
  lines.normals.assign(lines.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  dots.normals.assign(dots.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  const int grey = scene.addMaterial("grey", glm::vec3(0.5f), 0.0f, 0.5f);
  const int tint = scene.addMaterial("tint", glm::vec3(0.9f, 0.6f, 0.3f), 0.0f, 0.5f);
  scene.addObject(makePlane(), grey,
                  glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.6f * extent)));
  scene.addObject(std::move(lines), grey, glm::mat4(1.0f));
  scene.addObject(std::move(dots), tint, glm::mat4(1.0f));
  return scene;
}

// Pixels whose colour differs between two images of one size.
std::size_t differingPixels(const Image& a, const Image& b) {
  std::size_t n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) n += a.at(x, y).r != b.at(x, y).r || a.at(x, y).g != b.at(x, y).g || a.at(x, y).b != b.at(x, y).b;
  return n;
}

// endsTellReleasesApart: whether the scene puts segment ends where Mesa 22.3's and 25.0's
// end tests disagree, so that the CPU drawing them by the other release's
// test must differ from llvmpipe (the test of the detection itself).
void checkAgreement(const std::string& name, const Scene& scene, const RenderSettings& settings, bool endsTellReleasesApart = false) {
  FrameInputs frame = buildFrameInputs(scene, settings);
  const auto glRenderer = makeGlRenderer(GlContextKind::OsMesa);
  frame.lineEnds = lineEndTestOf(glRenderer->description());  // the CPU follows the llvmpipe it is held against
  const Image gl = glRenderer->render(scene, frame).image;
  test::writeTestImage(name, gl);
  const Image cpu = makeCpuRenderer(2)->render(scene, frame).image;
  if (endsTellReleasesApart) {
    FrameInputs other = frame;
    other.lineEnds = frame.lineEnds == LineEndTest::Mesa22 ? LineEndTest::Mesa25 : LineEndTest::Mesa22;
    CHECK(differingPixels(gl, makeCpuRenderer(2)->render(scene, other).image) > 0);
  }
  test::writeTestImage(name + "_cpu", cpu);
  REQUIRE(gl.width() == cpu.width());
  REQUIRE(gl.height() == cpu.height());
  std::size_t differing = 0, lit = 0;
  const Rgba8 background = cpu.at(0, 0);
  for (int y = 0; y < cpu.height(); ++y)
    for (int x = 0; x < cpu.width(); ++x) {
      const Rgba8 a = gl.at(x, y), b = cpu.at(x, y);
      if ((a.r != b.r || a.g != b.g || a.b != b.b) && differing++ < 8)
        MESSAGE(name << ": pixel (" << x << ", " << y << ") is " << test::describe(a) << " in OpenGL, " << test::describe(b) << " on the CPU");
      if (b.r != background.r || b.g != background.g || b.b != background.b) ++lit;
    }
  std::size_t fromReference = 0;  // the one-triangle-at-a-time reference draws lines with the same set-up
  const Image reference = makeReferenceRenderer()->render(scene, frame).image;
  for (int y = 0; y < cpu.height(); ++y)
    for (int x = 0; x < cpu.width(); ++x) fromReference += reference.at(x, y).r != cpu.at(x, y).r || reference.at(x, y).g != cpu.at(x, y).g;
  CHECK(fromReference == 0);
  INFO(name << ": " << differing << " of " << cpu.width() * cpu.height() << " pixels differ, " << lit << " drawn");
  CHECK(differing == 0);
  CHECK(lit > static_cast<std::size_t>(cpu.width() * cpu.height() / 20));  // not a blank image
}

}  // namespace

TEST_CASE("the segment-end test is read from the driver's version string") {
  CHECK(lineEndTestOf("gl: llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6 via osmesa") == LineEndTest::Mesa22);
  CHECK(lineEndTestOf("4.5 (Core Profile) Mesa 25.0.7-2+deb13u1") == LineEndTest::Mesa25);
  CHECK(lineEndTestOf("4.5 (Core Profile) Mesa 9.2.1") == LineEndTest::Mesa22);
  CHECK(lineEndTestOf("4.6.0 NVIDIA 550.54") == LineEndTest::Mesa25);
}

TEST_CASE("llvmpipe's GL_LINES and GL_POINTS equal the CPU backend's segments and points, clipped, in perspective") {
  std::mt19937 random(174);
  for (const auto& [width, height] : {std::pair{160, 120}, std::pair{61, 47}}) {
    const Scene scene = lineScene(random, 2.5f, false, 400, 400);
    RenderSettings settings = test::smallSettings(ShadingMode::Phong, false);
    settings.width = width, settings.height = height;
    settings.camera.source = Source::Manual;
    settings.camera.eye = {0.0f, 0.0f, 3.0f};
    settings.camera.near = 0.5f;  // the near plane cuts the segments that reach z > 2.5
    checkAgreement("lines_perspective_" + std::to_string(width), scene, settings);
  }
}

TEST_CASE("llvmpipe's GL_LINES and GL_POINTS equal the CPU backend's with ends on pixel centres, edges and corners") {
  std::mt19937 random(2026);
  for (const int size : {64, 63}) {
    const Scene scene = lineScene(random, 0.5f * static_cast<float>(size), true, 300, 300);
    RenderSettings settings = test::smallSettings(ShadingMode::Flat, false);
    settings.width = settings.height = size;
    settings.camera.source = Source::Manual;
    settings.camera.projection = ProjectionKind::Parallel;
    settings.camera.eye = {0.0f, 0.0f, 2.0f * static_cast<float>(size)};
    settings.camera.parallelWidth = static_cast<float>(size);  // one world unit per pixel
    settings.camera.far = 4.0f * static_cast<float>(size);
    checkAgreement("lines_parallel_" + std::to_string(size), scene, settings, size == 64);  // 13 of its pixels tell 22.3 from 25.0
  }
}

