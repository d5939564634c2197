// The course's fog (renderer/PIPELINE.md, "Fog"): the factor of
// each mode, the eye depth from 1/w and from the window depth, and what a
// rendered frame shows with it.
#include <cmath>
#include <limits>

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "shading/fog.h"
#include "cpu_test_scenes.h"
#include "pipeline/frame_inputs.h"
#include "scene/default_scene.h"
#include "settings/settings_json.h"

using namespace facet;

TEST_CASE("fog: linear is 1 at fog.start and 0 at fog.end, the exponentials are e^-(density d) and e^-(density d)^2, NaN gives 0") {
  FrameInputs::Fog fog;
  fog.mode = FogMode::Linear;
  fog.start = 2.0f, fog.end = 10.0f;
  CHECK(fogFactor(fog, 2.0f) == 1.0f);
  CHECK(fogFactor(fog, 10.0f) == 0.0f);
  CHECK(fogFactor(fog, 6.0f) == 0.5f);
  CHECK(fogFactor(fog, 1.0f) == 1.0f);   // nearer than the start: clamped
  CHECK(fogFactor(fog, 50.0f) == 0.0f);  // beyond the end
  CHECK(fogFactor(fog, std::numeric_limits<float>::quiet_NaN()) == 0.0f);
  fog.density = 0.25f;
  for (const float d : {0.5f, 4.0f, 9.0f, 20.0f}) {
    CAPTURE(d);
    fog.mode = FogMode::Exponential;
    CHECK(fogFactor(fog, d) == doctest::Approx(std::exp(-0.25 * d)).epsilon(2e-6));
    fog.mode = FogMode::Exponential2;
    CHECK(fogFactor(fog, d) == doctest::Approx(std::exp(-(0.25 * d) * (0.25 * d))).epsilon(2e-6));
  }
  fog.mode = FogMode::Exponential;
  CHECK(fogFactor(fog, 0.0f) == 1.0f);
  // C = C_fog + f (C - C_fog): f = 1 keeps the surface, f = 0 gives the fog colour.
  fog.color = {0.2f, 0.4f, 0.6f};
  CHECK(fogged(fog, glm::vec3(1.0f, 0.0f, 0.5f), 0.0f) == glm::vec3(1.0f, 0.0f, 0.5f));
  CHECK(fogged(fog, glm::vec3(1.0f, 0.0f, 0.5f), 1e6f) == fog.color);
  fog.mode = FogMode::None;
  CHECK(fogged(fog, glm::vec3(1.0f, 0.0f, 0.5f), 1e6f) == glm::vec3(1.0f, 0.0f, 0.5f));
}

#if defined(__SSE2__)
TEST_CASE("fog: four lanes give each lane's scalar factor, bit for bit") {
  for (const FogMode mode : {FogMode::Linear, FogMode::Exponential, FogMode::Exponential2}) {
    FrameInputs::Fog fog;
    fog.mode = mode;
    fog.start = 1.5f, fog.end = 33.0f, fog.density = 0.07f;
    for (float d0 = 0.0f; d0 < 60.0f; d0 += 0.37f) {
      alignas(16) float d[4] = {d0, d0 * 1.01f, d0 + 7.0f, d0 * 0.5f}, out[4];
      _mm_store_ps(out, fogFactor(fog, Float4(_mm_load_ps(d))).v);
      for (int k = 0; k < 4; ++k) CHECK(out[k] == fogFactor(fog, d[k]));
    }
  }
}
#endif

TEST_CASE("fog: the eye depth is w·cot(theta) under perspective and N + z (F - N) under parallel projection") {
  const Scene scene = makeDefaultScene();
  RenderSettings s;
  s.camera.source = Source::Manual;  // the settings' camera: perspective, then parallel
  FrameInputs frame = buildFrameInputs(scene, s);
  REQUIRE(frame.perspective);
  for (const float z : {0.5f, 3.0f, 17.0f, 80.0f}) {
    const glm::vec4 clip = frame.clipFromEye * glm::vec4(0.3f, -0.2f, z, 1.0f);
    CAPTURE(z);
    CHECK(eyeDepth(frame, 1.0f / clip.w, 0.0f) == doctest::Approx(z).epsilon(1e-6));
  }
  s.camera.projection = ProjectionKind::Parallel;
  frame = buildFrameInputs(scene, s);
  REQUIRE_FALSE(frame.perspective);
  for (const float z : {0.5f, 3.0f, 17.0f, 80.0f}) {
    const glm::vec4 clip = frame.clipFromEye * glm::vec4(0.3f, -0.2f, z, 1.0f);
    CAPTURE(z);
    CHECK(eyeDepth(frame, 1.0f, clip.z / clip.w) == doctest::Approx(z).epsilon(1e-5));
  }
}

TEST_CASE("fog: a fog that ends before the nearest surface paints every surface pixel the fog colour, and the background stays") {
  const Scene scene = test::groundScene(2, {0.8f, 0.2f, 0.1f});
  RenderSettings s = test::topDownSettings(32);  // the ground is 10 units below the eye
  const Image clear = test::renderCpu(scene, s);
  s.fog.mode = FogMode::Linear;
  s.fog.start = 0.0f, s.fog.end = 1.0f;
  s.fog.color = {0.1f, 0.5f, 0.9f};
  const Image foggy = test::renderCpu(scene, s);
  int surface = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      if (clear.at(x, y) == test::expectedPixel(s.background)) continue;
      ++surface;
      CHECK(foggy.at(x, y) == test::expectedPixel(s.fog.color));
    }
  CHECK(surface > 900);  // the ground fills the view
  // A fog from 9 to 11 units leaves half of the colour at the ground's depth of 10.
  s.fog.start = 9.0f, s.fog.end = 11.0f;
  const Image half = test::renderCpu(scene, s);
  const Rgba8 h = half.at(16, 16), c = clear.at(16, 16), f = foggy.at(16, 16);
  CHECK((h.r < c.r && h.r > f.r));  // between the red ground and the blue fog, channel by channel
  CHECK((h.b > c.b && h.b < f.b));
}

TEST_CASE("fog: a linear fog's end must lie beyond its start, named by key") {
  CHECK_THROWS_WITH_AS(settingsFromJson(nlohmann::json::parse(R"({"fog": {"mode": "linear", "start": 5, "end": 5}})")),
                       "settings key 'fog.end': must be greater than fog.start", Error);
  CHECK_NOTHROW(settingsFromJson(nlohmann::json::parse(R"({"fog": {"mode": "exponential", "start": 5, "end": 5}})")));
  CHECK_THROWS_WITH_AS(settingsFromJson(nlohmann::json::parse(R"({"fog": {"mode": "thick"}})")), doctest::Contains("'fog.mode'"), Error);
  CHECK_THROWS_WITH_AS(settingsFromJson(nlohmann::json::parse(R"({"fog": {"density": -1}})")), doctest::Contains("'fog.density'"), Error);
}
