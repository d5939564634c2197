// alphaMode MASK (renderer/PIPELINE.md, "Rasterization" and "Textures"): the test itself,
// and what a cut-away fragment must not do: hide the ground behind it, win
// its pixel, or cast a shadow.
#include <cmath>
#include <limits>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "cpu/alpha_mask.h"
#include "cpu_test_scenes.h"
#include "math/transforms.h"
#include "cpu/cpu_renderer.h"
#include "cpu/reference/reference_renderer.h"
#include "pipeline/frame_inputs.h"

using namespace facet;

namespace {

constexpr int kSize = 128;

// Pixel of world point (x, 0, z) in topDownSettings' view.
Rgba8 seen(const Image& image, float x, float z) {
  return image.at(static_cast<int>((x + 2.0f) / 4.0f * kSize), static_cast<int>((2.0f - z) / 4.0f * kSize));
}

// A grey ground and, half a metre over it, a red 2x2 quad whose COLOR_0
// alpha runs from 0 at x = -1 to 1 at x = 1: MASK at 0.5 keeps x >= 0.
Scene maskedQuadScene(AlphaMode mode) {
  Scene scene = test::groundScene(1, {0.5f, 0.5f, 0.5f});
  Mesh quad;
  quad.positions = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}};
  quad.normals.assign(4, {0, 1, 0});
  quad.colors = {{1, 1, 1, 0}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 0}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  const int red = scene.addMaterial("red", {0.9f, 0.05f, 0.05f}, 0.0f, 1.0f);
  scene.materials[static_cast<std::size_t>(red)].alphaMode = mode;
  scene.materials[static_cast<std::size_t>(red)].doubleSided = true;
  scene.addObject(quad, red, translation({0.0f, 0.5f, 0.0f}));
  return scene;
}

RenderSettings shadowedTopDown() {
  Light sun;
  sun.kind = LightKind::Directional;
  sun.direction = glm::normalize(glm::vec3(0.0f, -1.0f, -0.5f));  // the quad's shadow falls 0.25 towards -z
  RenderSettings s = test::shadowedTopDownSettings(kSize, sun);
  s.ambient = 0.2f;
  return s;
}

bool reddish(Rgba8 p) { return p.r > 2 * p.g + 20; }

}  // namespace

TEST_CASE("the alpha mask keeps a fragment when (factor.a * COLOR_0.a) * texel.a reaches the cutoff, and a NaN alpha discards") {
  CourseMaterial m;
  m.masked = true;
  m.alphaCutoff = 0.5f;
  m.baseAlpha = 0.8f;
  const float vertex = 0.625f;  // 0.8 * 0.625 = 0.5 exactly
  const glm::vec4 opaque{1.0f}, half{1.0f, 1.0f, 1.0f, 0.5f};
  CHECK(fragmentAlpha(m, &vertex, &opaque) == 0.5f);
  CHECK(alphaKept(m, fragmentAlpha(m, &vertex, &opaque)));       // equal to the cutoff: kept
  CHECK_FALSE(alphaKept(m, fragmentAlpha(m, &vertex, &half)));   // 0.25
  CHECK(alphaKept(m, fragmentAlpha(m, nullptr, nullptr)));      // 0.8: no vertex colour, no texture
  CHECK_FALSE(alphaKept(m, std::numeric_limits<float>::quiet_NaN()));
}

TEST_CASE("a masked-away fragment shows what is behind it and casts no shadow, and the kept part draws and shadows as opaque") {
  for (const bool reference : {false, true}) {
    CAPTURE(reference);
    const Scene scene = maskedQuadScene(AlphaMode::Mask);
    const RenderSettings s = shadowedTopDown();
    const FrameInputs frame = buildFrameInputs(scene, s);
    const Image image = (reference ? makeReferenceRenderer() : makeCpuRenderer(2))->render(scene, frame).image;
    const Rgba8 litGround = seen(image, -1.6f, 1.6f);
    CHECK(reddish(seen(image, 0.5f, 0.0f)));          // kept: alpha 0.75
    CHECK(seen(image, -0.5f, 0.0f) == litGround);     // cut (alpha 0.25): the lit ground shows through
    CHECK(seen(image, -0.5f, -1.15f) == litGround);   // the cut half casts no shadow
    CHECK(seen(image, 0.5f, -1.15f).g < litGround.g);  // the kept half does
    // OPAQUE ignores alpha: the whole quad draws and shadows.
    const Scene opaque = maskedQuadScene(AlphaMode::Opaque);
    const Image solid = makeCpuRenderer(2)->render(opaque, buildFrameInputs(opaque, s)).image;
    CHECK(reddish(seen(solid, -0.5f, 0.0f)));
    CHECK(seen(solid, -0.5f, -1.15f).g < litGround.g);
  }
}
