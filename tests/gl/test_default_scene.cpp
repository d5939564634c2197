// The default scene rendered headless through OSMesa, in every shading mode,
// with and without shadows and back-face culling, checked at pixels computed
// from FrameInputs: where nothing is, on the sphere's lit and unlit sides, in
// the cube's shadow on the ground, at the sphere's specular highlight, and on the
// ground seen from below (two-sided lighting).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "../kept_shadow_maps.h"
#include "gl_test_support.h"
#include "scene/default_scene.h"

using namespace facet;

namespace {

constexpr ShadingMode kModes[] = {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong};

std::string modeName(ShadingMode mode) { return std::string(kShadingModeNames[static_cast<std::size_t>(mode)]); }

// Distance from point c to the segment a-b.
float segmentDistance(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  const glm::vec3 ab = b - a;
  const float t = glm::clamp(glm::dot(c - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
  return glm::length(a + t * ab - c);
}

// A visible point of the sphere with unit normal n: in front of it (toward
// the eye) and not behind another object, since the sphere is nearest there.
glm::vec3 onSphere(const test::BoundingSphere& sphere, glm::vec3 n) { return sphere.center + 0.97f * sphere.radius * n; }

struct SpherePoints {
  glm::vec3 lit, unlit;  // world space, both facing the eye
};

// The lit point faces the light and the eye; the unlit one faces the eye and away from the light.
SpherePoints spherePoints(const FrameInputs& frame, const test::BoundingSphere& sphere) {
  const glm::vec3 toLight = glm::normalize(frame.lights[0].light.position - sphere.center);
  const glm::vec3 toEye = glm::normalize(frame.eyePosition - sphere.center);
  SpherePoints points{onSphere(sphere, glm::normalize(toLight + 2.0f * toEye)), {}};
  for (float k = 0.0f; k < 4.0f; k += 0.05f) {
    const glm::vec3 n = glm::normalize(toEye - k * toLight);
    if (glm::dot(n, toLight) < -0.25f) {
      points.unlit = onSphere(sphere, n);
      break;
    }
  }
  REQUIRE(glm::dot(glm::normalize(points.unlit - sphere.center), toEye) > 0.2f);
  return points;
}

// Does the segment a-b pass through the box [-k, k]³ of a model space? (the slab test)
bool crossesModelBox(const glm::mat4& worldFromModel, glm::vec3 a, glm::vec3 b, float k) {
  const glm::mat4 modelFromWorld = glm::inverse(worldFromModel);
  const glm::vec3 ma(modelFromWorld * glm::vec4(a, 1.0f)), mb(modelFromWorld * glm::vec4(b, 1.0f));
  float t0 = 0.0f, t1 = 1.0f;
  for (int i = 0; i < 3; ++i) {
    const float d = mb[i] - ma[i];
    if (std::fabs(d) < 1e-9f) {
      if (std::fabs(ma[i]) > k) return false;
      continue;
    }
    const float ta = (-k - ma[i]) / d, tb = (k - ma[i]) / d;
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
    if (t0 > t1) return false;
  }
  return true;
}

// The centroid of a ground triangle deep in the cube's shadow (its corners
// and centroid all see the light through the cube's inner 60%, so PCF, flat
// shading's one factor per triangle and Gouraud's factor per vertex all
// agree), which the eye sees past every object.
glm::vec3 groundInCubeShadow(const Scene& scene, const FrameInputs& frame) {
  const FrameInstance& ground = frame.instances[0];
  const Mesh& plane = scene.meshes[static_cast<std::size_t>(ground.mesh)];
  const FrameInstance& cube = frame.instances[test::instanceWithMaterial(scene, frame, "blue paint")];
  std::vector<test::BoundingSphere> others;
  for (const char* material : {"red plastic", "green rubber", "gold"})
    others.push_back(test::boundingSphere(scene, frame, test::instanceWithMaterial(scene, frame, material)));
  const glm::vec3 light = frame.lights[0].light.position;
  for (std::size_t t = 0; t + 2 < plane.indices.size(); t += 3) {
    glm::vec3 corners[3];
    for (int k = 0; k < 3; ++k) corners[k] = glm::vec3(ground.worldFromModel * glm::vec4(plane.positions[plane.indices[t + static_cast<std::size_t>(k)]], 1.0f));
    const glm::vec3 centroid = (corners[0] + corners[1] + corners[2]) / 3.0f;
    bool shadowed = crossesModelBox(cube.worldFromModel, centroid, light, 0.6f);
    for (glm::vec3 c : corners) shadowed = shadowed && crossesModelBox(cube.worldFromModel, c, light, 0.6f);
    bool seen = !crossesModelBox(cube.worldFromModel, centroid, frame.eyePosition, 1.1f);
    for (const test::BoundingSphere& o : others) seen = seen && segmentDistance(centroid, frame.eyePosition, o.center) > 1.02f * o.radius;
    if (shadowed && seen) return centroid;
  }
  FAIL("no ground triangle in the cube's shadow is in view");
  return {};
}

Rgba8 pixelAt(const Image& image, glm::ivec2 p) {
  REQUIRE(p.x >= 0);
  REQUIRE(p.y >= 0);
  REQUIRE(p.x < image.width());
  REQUIRE(p.y < image.height());
  return image.at(p.x, p.y);
}

}  // namespace

TEST_CASE("every mode, with and without shadows and culling: background where nothing is, the sphere lit on the light's side") {
  const Scene scene = makeDefaultScene();
  for (ShadingMode mode : kModes)
    for (bool shadows : {true, false})
      for (bool cull : {true, false}) {
        const std::string name = "default_" + modeName(mode) + (shadows ? "_shadows" : "_no_shadows") + (cull ? "_cull" : "_no_cull");
        CAPTURE(name);
        const FrameInputs frame = buildFrameInputs(scene, test::smallSettings(mode, shadows, cull));
        const Image image = test::renderHeadless(name, scene, frame);
        REQUIRE(image.width() == 160);
        REQUIRE(image.height() == 120);

        // The top corners see the sky: exactly the encoded, quantized background.
        const Rgba8 background = test::encodedPixel(frame.background);
        CHECK(test::describe(image.at(0, 119)) == test::describe(background));
        CHECK(test::describe(image.at(159, 119)) == test::describe(background));
        int opaque = 0;
        for (int y = 0; y < image.height(); ++y)
          for (int x = 0; x < image.width(); ++x) opaque += image.at(x, y).a == 255;
        CHECK(opaque == 160 * 120);

        // The red sphere: bright and red where the light falls, much darker on its far side.
        const test::BoundingSphere sphere = test::boundingSphere(scene, frame, test::instanceWithMaterial(scene, frame, "red plastic"));
        const SpherePoints points = spherePoints(frame, sphere);
        const Rgba8 lit = pixelAt(image, test::pixelOf(frame, points.lit));
        const Rgba8 unlit = pixelAt(image, test::pixelOf(frame, points.unlit));
        CAPTURE(test::describe(lit));
        CAPTURE(test::describe(unlit));
        CHECK(lit.r > 150);
        CHECK(lit.r > lit.g + 60);  // red plastic, not the ground or the background
        CHECK(unlit.r > unlit.g + 10);
        CHECK(test::luma(lit) > test::luma(unlit) + 25.0);
      }
}

TEST_CASE("the cube casts its shadow on the ground: shadows on darken that ground pixel, and only where the shadow is") {
  const Scene scene = makeDefaultScene();
  for (ShadingMode mode : kModes) {
    CAPTURE(modeName(mode));
    const FrameInputs withShadows = buildFrameInputs(scene, test::smallSettings(mode, true));
    const FrameInputs withoutShadows = buildFrameInputs(scene, test::smallSettings(mode, false));
    const Image on = test::renderHeadless("shadow_on_" + modeName(mode), scene, withShadows);
    const Image off = test::renderHeadless("shadow_off_" + modeName(mode), scene, withoutShadows);

    const glm::vec3 ground = groundInCubeShadow(scene, withShadows);
    const Rgba8 shadowed = pixelAt(on, test::pixelOf(withShadows, ground));
    const Rgba8 unshadowed = pixelAt(off, test::pixelOf(withShadows, ground));
    CAPTURE(test::describe(shadowed));
    CAPTURE(test::describe(unshadowed));
    CHECK(std::abs(unshadowed.r - unshadowed.b) < 20);  // grey ground, not an object
    CHECK(test::luma(unshadowed) > 120.0);
    CHECK(test::luma(shadowed) < test::luma(unshadowed) - 40.0);

    // Ground right of the scene, nothing between it and the light: the same pixel either way.
    const glm::ivec2 open = test::pixelOf(withShadows, {3.0f, 0.0f, 1.0f});
    CHECK(test::describe(pixelAt(on, open)) == test::describe(pixelAt(off, open)));
  }
}

TEST_CASE("the specular highlight is at the pixel where the sphere reflects the light into the eye") {
  const Scene scene = makeDefaultScene();
  for (SpecularModel model : {SpecularModel::BlinnPhong, SpecularModel::Phong}) {
    CAPTURE(static_cast<int>(model));
    RenderSettings settings = test::smallSettings(ShadingMode::Phong, false);
    settings.width = 400;
    settings.height = 300;
    settings.specular = model;
    const FrameInputs frame = buildFrameInputs(scene, settings);
    const Image image = test::renderHeadless(std::string("highlight_") + (model == SpecularModel::Phong ? "phong" : "blinn_phong"), scene, frame);

    // The mirror point: its normal halves the angle between the light and the eye (R = V, N = H).
    const test::BoundingSphere sphere = test::boundingSphere(scene, frame, test::instanceWithMaterial(scene, frame, "red plastic"));
    const float radius = glm::length(glm::vec3(frame.instances[test::instanceWithMaterial(scene, frame, "red plastic")].worldFromModel[0]));
    glm::vec3 p = sphere.center + radius * glm::normalize(frame.eyePosition - sphere.center);
    for (int i = 0; i < 50; ++i) {
      const glm::vec3 n = glm::normalize(glm::normalize(frame.lights[0].light.position - p) + glm::normalize(frame.eyePosition - p));
      p = sphere.center + radius * n;
    }
    const glm::vec2 predicted = test::windowOf(frame, p);

    // The brightest pixel (green channel: the red plastic has almost none but the highlight is white) near it.
    glm::ivec2 brightest{-1, -1};
    int brightestGreen = -1;
    const glm::ivec2 centre = test::pixelOf(frame, p);
    for (int y = centre.y - 15; y <= centre.y + 15; ++y)
      for (int x = centre.x - 15; x <= centre.x + 15; ++x)
        if (image.at(x, y).g > brightestGreen) {
          brightestGreen = image.at(x, y).g;
          brightest = {x, y};
        }
    CAPTURE(predicted.x);
    CAPTURE(predicted.y);
    CAPTURE(brightest.x);
    CAPTURE(brightest.y);
    CHECK(brightestGreen > 200);
    CHECK(std::abs(static_cast<float>(brightest.x) + 0.5f - predicted.x) <= 1.5f);
    CHECK(std::abs(static_cast<float>(brightest.y) + 0.5f - predicted.y) <= 1.5f);
    // Away from it, the sphere is its diffuse red.
    CHECK(image.at(centre.x + 12, centre.y - 12).g < brightestGreen - 100);
  }
}

TEST_CASE("the ground seen from below: culled with culling on, and lit as its back side (ambient only) with culling off") {
  const Scene scene = makeDefaultScene();
  RenderSettings settings = test::smallSettings();
  settings.camera.source = Source::Manual;
  settings.camera.eye = {0.3f, -4.0f, 0.2f};
  settings.camera.reference = {0.3f, 0.0f, 0.2f};  // nothing stands above this ground point
  settings.camera.up = {0.0f, 0.0f, -1.0f};
  for (ShadingMode mode : kModes)
    for (bool cull : {true, false}) {
      CAPTURE(modeName(mode));
      CAPTURE(cull);
      settings.shading = mode;
      settings.cullBackFaces = cull;
      const FrameInputs frame = buildFrameInputs(scene, settings);
      const Image image = test::renderHeadless("from_below_" + modeName(mode) + (cull ? "_cull" : "_no_cull"), scene, frame);
      const Rgba8 centre = pixelAt(image, test::pixelOf(frame, settings.camera.reference));
      if (cull) {
        CHECK(test::describe(centre) == test::describe(test::encodedPixel(frame.background)));
        continue;
      }
      // Two-sided lighting: the normal turns down, away from the light above: I = k_a·I_a·O_d.
      const CourseMaterial& ground = frame.materials[static_cast<std::size_t>(frame.instances[0].material)];
      const Rgba8 expected = test::encodedPixel(ground.ka * frame.ambient * ground.baseColor);
      CAPTURE(test::describe(centre));
      CAPTURE(test::describe(expected));
      CHECK(std::abs(centre.r - expected.r) <= 1);
      CHECK(std::abs(centre.g - expected.g) <= 1);
      CHECK(std::abs(centre.b - expected.b) <= 1);
      CHECK(expected.r > 40);  // not black: the ambient term is there
    }
}

TEST_CASE("with lighting reduced to O_d, every shading mode gives the same image: the modes cover the same pixels") {
  const Scene scene = makeDefaultScene();
  std::vector<Image> images;
  for (ShadingMode mode : kModes) {
    RenderSettings settings = test::smallSettings(mode, false, false);
    settings.width = 317;  // odd sizes: window coordinates are inexact and llvmpipe's rounding shows
    settings.height = 239;
    settings.ambient = 1.0f;
    settings.material.ka = 1.0f;
    settings.material.kd = 0.0f;
    settings.material.ks = 0.0f;
    const FrameInputs frame = buildFrameInputs(scene, settings);
    images.push_back(test::renderHeadless("base_color_" + modeName(mode), scene, frame));
    // The sphere shows its base colour exactly.
    const std::size_t sphere = test::instanceWithMaterial(scene, frame, "red plastic");
    const Rgba8 expected = test::encodedPixel(frame.materials[static_cast<std::size_t>(frame.instances[sphere].material)].baseColor);
    const Rgba8 actual = pixelAt(images.back(), test::pixelOf(frame, test::boundingSphere(scene, frame, sphere).center));
    CHECK(std::abs(actual.r - expected.r) <= 1);
    CHECK(std::abs(actual.g - expected.g) <= 1);
    CHECK(std::abs(actual.b - expected.b) <= 1);
  }
  CHECK(images[0] == images[2]);
  CHECK(images[1] == images[2]);
}

TEST_CASE("the GL renderer keeps its shadow maps while the light, the geometry and the shadow settings stay, and redraws them when they change") {
  test::checkShadowMapsKept([] { return makeGlRenderer(GlContextKind::OsMesa); });
}

TEST_CASE("EGL renders the same pixels as OSMesa") {
  const Scene scene = makeDefaultScene();
  for (ShadingMode mode : kModes) {
    CAPTURE(modeName(mode));
    const FrameInputs frame = buildFrameInputs(scene, test::smallSettings(mode, true, false));
    const Image osmesa = test::renderHeadless("context_osmesa_" + modeName(mode), scene, frame, GlContextKind::OsMesa);
    const Image egl = test::renderHeadless("context_egl_" + modeName(mode), scene, frame, GlContextKind::Egl);
    CHECK(osmesa == egl);
  }
}

TEST_CASE("one renderer draws frame after frame: the same image again, then other sizes and settings") {
  const Scene scene = makeDefaultScene();
  const std::unique_ptr<Renderer> renderer = makeGlRenderer(GlContextKind::OsMesa);
  const FrameInputs frame = buildFrameInputs(scene, test::smallSettings());
  const RenderResult first = renderer->render(scene, frame);
  const RenderResult second = renderer->render(scene, frame);
  CHECK(first.image == second.image);
  std::vector<std::string> passes;
  for (const PassTiming& t : first.timings) passes.push_back(t.pass);
  CHECK(passes == std::vector<std::string>{"scene upload", "shader compile + link", "shadow pass (6 maps)", "lit pass, encoded as drawn", "read-back"});
  passes.clear();
  for (const PassTiming& t : second.timings) passes.push_back(t.pass);
  // Uploaded, compiled and the shadow maps drawn once: the second frame is the same frame.
  CHECK(passes == std::vector<std::string>{"shadow pass (6 maps kept)", "lit pass, encoded as drawn", "read-back"});

  RenderSettings other = test::smallSettings(ShadingMode::Flat, false, false);
  other.width = 97;
  other.height = 61;
  other.shadows.mapSize = 256;
  const RenderResult resized = renderer->render(scene, buildFrameInputs(scene, other));
  CHECK(resized.image.width() == 97);
  CHECK(resized.image.height() == 61);
  CHECK(renderer->render(scene, frame).image == first.image);
  // Another scene (a copy counts as one) is uploaded again.
  const Scene copy = scene;
  CHECK(renderer->render(copy, frame).timings.front().pass == "scene upload");
  CHECK(renderer->description().find("gl: llvmpipe") == 0);
  CHECK(renderer->description().find(" via osmesa") != std::string::npos);
}
