// A frame where nothing blends or averages colours is encoded as the lit
// pass draws it (renderer/PIPELINE.md, "The colour buffer and the
// resolve"): the same bytes as the float buffer and the resolve give, for
// every writer of the image (the background clear and its full-frame draw,
// triangles, lines and points), every blending equation's storage of the
// background, and the z-buffer read back after it.
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <doctest/doctest.h>

#include "gl/frame_renderer.h"
#include "gl_test_support.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/frame_spine.h"
#include "scene/default_scene.h"
#include "scene/load_scene.h"

using namespace facet;
using Encoding = gl::GlFrameRenderer::Encoding;

namespace {

struct Variation {
  const char* name;
  const char* file;  // images/encoded_as_drawn_<file>.png
  void (*apply)(RenderSettings&);
};

// Mesh lines and points over the default scene: a square's outline and its corners.
void addLinesAndPoints(Scene& scene) {
  Mesh lines, dots;
  lines.name = "outline", dots.name = "corners";
  const glm::vec3 corners[] = {{-1.5f, 0.2f, 1.0f}, {1.5f, 0.2f, 1.0f}, {1.5f, 1.8f, 1.0f}, {-1.5f, 1.8f, 1.0f}};
  for (std::uint32_t i = 0; i < 4; ++i) {
    lines.positions.push_back(corners[i]);
    lines.colors.emplace_back(0.9f, 0.35f, 0.05f, 1.0f);
    lines.lines.insert(lines.lines.end(), {i, (i + 1) % 4});
    dots.positions.push_back(corners[i] + glm::vec3(0.0f, 0.0f, 0.1f));
    dots.points.push_back(i);
  }
  lines.normals.assign(lines.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  dots.normals.assign(dots.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  const int tint = scene.addMaterial("tint", glm::vec3(0.2f, 0.6f, 0.9f), 0.0f, 0.5f);
  scene.addObject(std::move(lines), tint, glm::mat4(1.0f));
  scene.addObject(std::move(dots), tint, glm::mat4(1.0f));
}

}  // namespace

TEST_CASE("a frame nothing blends or averages, encoded as drawn, has the bytes and depths of the float buffer and the resolve") {
  test::GlHarness harness;
  gl::GlFrameRenderer frames([&](const char* name) { return harness.context->getProcAddress(name); });
  const Variation variations[] = {
      {"phong, shadows", "phong_shadows", [](RenderSettings&) {}},
      // (C·a)/a is not C for every float: the clear must be the resolve's levels of what would be held
      {"premultiplied, a background of alpha 0.3", "premultiplied_background",
       [](RenderSettings& s) {
         s.blending = Blending::Premultiplied;
         s.background = {0.7f, 0.11f, 0.33f};
         s.backgroundAlpha = 0.3f;
       }},
      {"straight, background alpha 0.6", "straight_background", [](RenderSettings& s) { s.backgroundAlpha = 0.6f; }},
      {"the environment map behind", "environment", [](RenderSettings& s) { s.environment.map = std::string(FACET_ASSETS) + "/environment/sky_cube.png"; }},
      {"the environment map behind, premultiplied, alpha 0.45", "environment_premultiplied",
       [](RenderSettings& s) {
         s.environment.map = std::string(FACET_ASSETS) + "/environment/sky_cube.png";
         s.blending = Blending::Premultiplied;
         s.backgroundAlpha = 0.45f;
       }},
      {"flat, linear fog, painter's algorithm", "flat_fog_painter",
       [](RenderSettings& s) {
         s.shading = ShadingMode::Flat;
         s.fog.mode = FogMode::Linear;
         s.hsr = HiddenSurface::Painter;
       }},
      {"gouraud, exponential fog", "gouraud_fog", [](RenderSettings& s) {
         s.shading = ShadingMode::Gouraud;
         s.fog.mode = FogMode::Exponential;
       }},
  };
  for (const Variation& variation : variations) {
    CAPTURE(std::string(variation.name));
    Scene loaded = makeDefaultScene();
    addLinesAndPoints(loaded);
    RenderSettings settings = test::smallSettings();
    variation.apply(settings);
    const PreparedFrame prepared = FrameSpine(std::make_shared<const Scene>(std::move(loaded))).frame(settings);
    const Scene& scene = *prepared.scene;
    const FrameInputs& frame = prepared.inputs;
    frames.uploadScene(scene);

    const std::vector<PassTiming> plainPasses = frames.drawFrame(scene, frame, Encoding::ByResolve);
    const Image plain = frames.readImage();
    const std::vector<PassTiming> asDrawnPasses = frames.drawFrame(scene, frame);
    const Image asDrawn = frames.readImage();
    test::writeTestImage(std::string("encoded_as_drawn_") + variation.file, asDrawn);

    // The two paths are the ones asked for: the resolve after a float buffer, and none.
    const auto hasPass = [](const std::vector<PassTiming>& passes, const std::string& name) {
      for (const PassTiming& pass : passes)
        if (pass.pass == name) return true;
      return false;
    };
    CHECK(hasPass(plainPasses, "resolve"));
    CHECK_FALSE(hasPass(asDrawnPasses, "resolve"));
    CHECK(hasPass(asDrawnPasses, "lit pass, encoded as drawn"));

    // Not a blank frame: lit pixels, the lines' orange and the background all there.
    int distinct = 0;
    for (int y = 0; y < plain.height(); y += 7)
      for (int x = 0; x < plain.width(); x += 7)
        if (plain.at(x, y).r != plain.at(0, 0).r || plain.at(x, y).g != plain.at(0, 0).g) ++distinct;
    CHECK(distinct > 50);

    int differing = 0;
    for (int y = 0; y < plain.height(); ++y)
      for (int x = 0; x < plain.width(); ++x) {
        const Rgba8 a = plain.at(x, y), b = asDrawn.at(x, y);
        if (a.r != b.r || a.g != b.g || a.b != b.b || a.a != b.a) ++differing;
      }
    CHECK(differing == 0);
    CHECK(asDrawn.at(0, 0).a == plain.at(0, 0).a);

    // The z-buffer the frame leaves: the same in both targets.
    frames.drawFrame(scene, frame, Encoding::ByResolve);
    const std::vector<float> plainDepth = frames.drawDepth(scene, frame);
    const std::vector<float> depth = frames.drawDepth(scene, frame);
    CHECK(depth == plainDepth);
  }
}

TEST_CASE("a frame with blended draws or several samples is not encoded as drawn") {
  test::GlHarness harness;
  gl::GlFrameRenderer frames([&](const char* name) { return harness.context->getProcAddress(name); });
  const auto resolves = [&](const Scene& scene, const RenderSettings& settings) {
    frames.uploadScene(scene);
    bool resolved = false;
    for (const PassTiming& pass : frames.drawFrame(scene, buildFrameInputs(scene, settings))) resolved = resolved || pass.pass == "resolve";
    return resolved;
  };
  RenderSettings settings = test::smallSettings();
  CHECK_FALSE(resolves(makeDefaultScene(), settings));
  CHECK(resolves(loadScene(std::string(FACET_ASSETS) + "/transparency.gltf"), settings));
  settings.antialiasing.samples = 4;
  CHECK(resolves(makeDefaultScene(), settings));
}
