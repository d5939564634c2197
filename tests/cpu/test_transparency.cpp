// Transparency (renderer/PIPELINE.md, "Transparency"): which
// materials blend, the back-to-front order, the two blending equations on
// whole frames (against the course's formulas in double precision), depth
// tested without depth writes, the triangle-id pass, and the shadow rule.
#include <cmath>
#include <cstdlib>

#include <doctest/doctest.h>

#include "cpu/cpu_renderer.h"
#include "cpu_test_scenes.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/material_coefficients.h"
#include "pipeline/transparency_order.h"

using namespace facet;

namespace {

constexpr int kSize = 64;

// A horizontal square of side 2·half at height y (nearer the top-down eye when higher), centred on (cx, cz), facing +y.
Mesh square(float y, float cx, float cz, float half) {
  Mesh m;
  for (const glm::vec2 c : {glm::vec2(-1, 1), glm::vec2(1, 1), glm::vec2(1, -1), glm::vec2(-1, -1)}) {
    m.positions.push_back({cx + half * c.x, y, cz + half * c.y});
    m.normals.push_back({0, 1, 0});
  }
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// A square whose colour is its emission alone (the settings below light nothing), with alpha `alpha` and alphaMode `mode`.
void addSquare(Scene& scene, float y, float cx, float cz, float half, glm::vec3 color, float alpha, AlphaMode mode) {
  const int material = scene.addMaterial("square", glm::vec3(0.0f), 0.0f, 1.0f);
  scene.materials[static_cast<std::size_t>(material)].emissive = color;
  scene.materials[static_cast<std::size_t>(material)].baseColor.a = alpha;
  scene.materials[static_cast<std::size_t>(material)].alphaMode = mode;
  scene.addObject(square(y, cx, cz, half), material, glm::mat4(1.0f));
}

// No light and no ambient: each surface shows its emission k_e exactly.
RenderSettings unlit() {
  RenderSettings s = test::topDownSettings(kSize);
  s.ambient = 0.0f;
  return s;
}

Rgba8 at(const Image& image, float x, float z) {
  return image.at(static_cast<int>((x + 2.0f) / 4.0f * kSize), static_cast<int>((2.0f - z) / 4.0f * kSize));
}

// The course's equations in double: straight C_o = (C_f α_f + C_b α_b (1 − α_f)) / α_o, α_o = α_f + α_b (1 − α_f).
struct Held {
  glm::dvec3 c;
  double a;
};
Held over(Held b, glm::dvec3 f, double a) {
  const double out = a + b.a * (1 - a);
  return {(f * a + b.c * b.a * (1 - a)) / out, out};
}

// Within one level of the double-precision value: the renderer rounds in float.
bool near(Rgba8 got, Held expected) {
  const Rgba8 e = test::expectedPixel(glm::vec3(expected.c));
  const int alpha = static_cast<int>(std::floor(expected.a * 255.0 + 0.5));
  return std::abs(got.r - e.r) <= 1 && std::abs(got.g - e.g) <= 1 && std::abs(got.b - e.b) <= 1 && std::abs(got.a - alpha) <= 1;
}

}  // namespace

TEST_CASE("transparency: which materials blend, and material.opacity in the factor's place") {
  Material blend, mask, opaque;
  blend.alphaMode = AlphaMode::Blend;
  blend.baseColor.a = 0.4f;
  mask.alphaMode = AlphaMode::Mask;
  mask.alphaCutoff = 0.8f;
  TransparencySettings t;
  t.shadowCutoff = 0.25f;
  const CourseMaterial b = courseMaterial(blend, {}, t);
  CHECK((b.blended && !b.masked && b.baseAlpha == 0.4f && b.alphaCutoff == 0.25f && masksShadow(b)));  // the shadow pass's cutoff
  CHECK((courseMaterial(mask, {}, t).masked && !courseMaterial(mask, {}, t).blended && courseMaterial(mask, {}, t).alphaCutoff == 0.8f));
  CHECK(!masksShadow(courseMaterial(opaque, {}, t)));
  MaterialOverrides o;
  o.opacity = 0.5f;  // every material blends, MASK too, with α's factor 0.5
  for (const Material& m : {blend, mask, opaque}) {
    const CourseMaterial c = courseMaterial(m, o, t);
    CHECK((c.blended && !c.masked && c.baseAlpha == 0.5f));
  }
  o.opacity = 1.0f;  // the factor replaced, the modes kept
  CHECK((courseMaterial(opaque, o, t).baseAlpha == 1.0f && !courseMaterial(opaque, o, t).blended));
  CHECK((courseMaterial(mask, o, t).masked && courseMaterial(blend, o, t).blended && courseMaterial(blend, o, t).baseAlpha == 1.0f));
}

TEST_CASE("transparency: blended triangles back to front by object or by triangle, opaque ones not listed") {
  Scene scene;
  addSquare(scene, 0.0f, 0, 0, 2.0f, {0.2f, 0.2f, 0.2f}, 1.0f, AlphaMode::Opaque);  // triangles 0, 1
  addSquare(scene, 2.0f, 0, 0, 0.5f, {1, 0, 0}, 0.5f, AlphaMode::Blend);             // 2, 3: the nearest
  addSquare(scene, 1.0f, 0, 0, 0.5f, {0, 0, 1}, 0.5f, AlphaMode::Blend);             // 4, 5
  // 6, 7: one triangle far (y = 0.5 at its lowest corner), the box's centre the farthest too
  addSquare(scene, 0.5f, 1.0f, 1.0f, 0.5f, {0, 1, 0}, 0.5f, AlphaMode::Blend);
  RenderSettings s = unlit();
  CHECK(buildFrameInputs(scene, s).transparentOrder == std::vector<std::uint32_t>{6, 7, 4, 5, 2, 3});
  s.transparency.sort = TransparencySort::Triangle;
  CHECK(buildFrameInputs(scene, s).transparentOrder == std::vector<std::uint32_t>{6, 7, 4, 5, 2, 3});
  // Tilt the far square: corners 0, 1, 2 (triangle 6) rise to y = 1.6, corner 3 stays at 0.5. By triangle
  // (the farthest corner's depth 10 - y) its halves part: 7 (9.5), the blue square (9), 6 (8.4), the red (8);
  // by object it moves whole, its box's centre at y = 1.05 (8.95) just nearer than the blue square's (9).
  for (int k = 0; k < 3; ++k) scene.meshes[3].positions[static_cast<std::size_t>(k)].y = 1.6f;
  CHECK(buildFrameInputs(scene, s).transparentOrder == std::vector<std::uint32_t>{7, 4, 5, 6, 2, 3});
  s.transparency.sort = TransparencySort::Object;
  CHECK(buildFrameInputs(scene, s).transparentOrder == std::vector<std::uint32_t>{4, 5, 6, 7, 2, 3});
  s.hsr = HiddenSurface::Painter;  // no z-buffer to test against: drawn opaque, said so
  const FrameInputs painted = buildFrameInputs(scene, s);
  CHECK(painted.transparentOrder.empty());
  CHECK(!painted.materials[1].blended);
  REQUIRE(!painted.warnings.empty());
  CHECK(painted.warnings.back() == "hsr painter: blended materials are drawn opaque (transparency is drawn with hsr zbuffer)");
}

TEST_CASE("transparency: both equations on a frame, whatever the file order, and nothing blended over an opaque surface in front") {
  Scene scene;
  const glm::dvec3 grey(0.2), red(0.9, 0.1, 0.05), blue(0.05, 0.2, 0.9), green(0.1, 0.8, 0.1);
  addSquare(scene, 0.0f, 0.0f, 0.0f, 2.0f, glm::vec3(grey), 1.0f, AlphaMode::Opaque);
  addSquare(scene, 2.0f, -0.4f, 0.0f, 0.8f, glm::vec3(red), 0.6f, AlphaMode::Blend);   // near, listed first
  addSquare(scene, 1.0f, 0.4f, 0.0f, 0.8f, glm::vec3(blue), 0.5f, AlphaMode::Blend);   // far, listed second
  addSquare(scene, 3.0f, 0.0f, -1.5f, 0.3f, glm::vec3(green), 1.0f, AlphaMode::Opaque); // opaque, above both blended squares' far edge
  addSquare(scene, 0.5f, 0.0f, -1.5f, 0.6f, {1, 1, 1}, 0.5f, AlphaMode::Blend);       // under the green one and the red and blue
  const Held ground{grey, 1.0};
  for (const Blending blending : {Blending::Straight, Blending::Premultiplied}) {
    CAPTURE(static_cast<int>(blending));
    RenderSettings s = unlit();
    s.blending = blending;
    const Image image = test::renderCpu(scene, s);
    CHECK(near(at(image, -1.0f, 0.5f), over(ground, red, 0.6)));                  // red alone
    CHECK(near(at(image, 1.0f, 0.5f), over(ground, blue, 0.5)));                   // blue alone
    CHECK(near(at(image, 0.0f, 0.5f), over(over(ground, blue, 0.5), red, 0.6)));   // blue drawn first, then red over it
    CHECK(near(at(image, 1.5f, -1.5f), ground));                                     // outside every square
    CHECK(at(image, 0.0f, -1.5f) == test::expectedPixel(glm::vec3(green)));         // nothing blended over the opaque square above
    CHECK(near(at(image, 0.5f, -1.7f), over(ground, glm::dvec3(1.0), 0.5)));         // the white one beside the green, over the ground
    // Against a transparent background the alpha channel carries the coverage.
    s.backgroundAlpha = 0.0f;
    scene.instances.erase(scene.instances.begin());  // no ground
    const Image clear = test::renderCpu(scene, s);
    scene.instances.insert(scene.instances.begin(), MeshInstance{0, glm::mat4(1.0f)});
    const Held none{glm::dvec3(0.0), 0.0};
    CHECK(near(at(clear, -1.0f, 0.5f), over(none, red, 0.6)));  // red itself, alpha level 153
    CHECK(at(clear, -1.0f, 0.5f).a == 153);
    CHECK(near(at(clear, 0.0f, 0.5f), over(over(none, blue, 0.5), red, 0.6)));  // α_o = 0.6 + 0.5·0.4 = 0.8, level 204
    CHECK(at(clear, 0.0f, 0.5f).a == 204);
    CHECK(at(clear, 1.5f, 1.5f).a == 0);
  }
}

TEST_CASE("transparency: blended triangles keep no pixel in the triangle-id pass, and are counted in depth complexity") {
  Scene scene;
  addSquare(scene, 0.0f, 0.0f, 0.0f, 2.0f, {0.2f, 0.2f, 0.2f}, 1.0f, AlphaMode::Opaque);
  addSquare(scene, 1.0f, 0.0f, 0.0f, 1.0f, {1, 0, 0}, 0.5f, AlphaMode::Blend);
  const FrameInputs frame = buildFrameInputs(scene, unlit());
  const std::vector<std::uint32_t> ids = *makeCpuRenderer(2)->render(scene, frame, {FrameOutput::TriangleIds}).triangleIds;
  const std::vector<std::uint32_t> counts = *makeCpuRenderer(2)->render(scene, frame, {FrameOutput::FragmentCounts}).fragmentCounts;
  const std::size_t middle = static_cast<std::size_t>(kSize / 2) * kSize + kSize / 2;
  CHECK((ids[middle] == 1 || ids[middle] == 2));  // the ground's triangles, 1-based
  CHECK(counts[middle] == 2);
}

TEST_CASE("transparency: a blended surface casts a shadow where its alpha reaches transparency.shadowCutoff") {
  Scene scene;
  addSquare(scene, 0.0f, 0.0f, 0.0f, 2.0f, {0.0f, 0.0f, 0.0f}, 1.0f, AlphaMode::Opaque);
  scene.materials[0].baseColor = {0.8f, 0.8f, 0.8f, 1.0f};
  addSquare(scene, 1.0f, 1.0f, 0.0f, 0.5f, {0.0f, 0.0f, 0.0f}, 0.6f, AlphaMode::Blend);
  Light sun;
  sun.kind = LightKind::Directional;
  sun.direction = glm::normalize(glm::vec3(-1.0f, -1.0f, 0.0f));  // the shadow falls 1 to the left of the square, on open ground
  RenderSettings s = test::shadowedTopDownSettings(kSize, sun);
  const auto ground = [&](float cutoff) {
    s.transparency.shadowCutoff = cutoff;
    return at(test::renderCpu(scene, s), 0.0f, 0.0f);
  };
  const Rgba8 shadowed = ground(0.6f), lit = ground(0.61f);
  CHECK(shadowed.r + 40 < lit.r);  // α = 0.6 casts at a cutoff of 0.6, not above it
  CHECK(ground(0.0f) == shadowed);
}
