// The ray-tracing backend (renderer/PIPELINE.md, "Ray tracing") held to the
// rasterizer where the two must agree (ray casting: the same triangle at
// every pixel but on triangle edges, the same colour where both see the
// same triangle), to hand-computed optics (a mirror, a glass slab, total
// internal reflection) and to the stopping conditions of the ray tree.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "common/error.h"
#include "common/thread_pool.h"
#include "cpu/cpu_renderer.h"
#include "math/transforms.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/microfacet.h"
#include "ray/camera_rays.h"
#include "ray/optics.h"
#include "ray/ray_renderer.h"
#include "ray/ray_tracer.h"
#include "ray/traced_scene.h"
#include "scene/cornell_box.h"
#include "scene/default_scene.h"
#include "scene/load_scene.h"
#include "scene/primitives.h"

using namespace facet;

namespace {

// The largest difference of two pixels' colour levels.
int levelDifference(Rgba8 a, Rgba8 b) { return std::max({std::abs(int{a.r} - b.r), std::abs(int{a.g} - b.g), std::abs(int{a.b} - b.b)}); }

// Whether pixel (x, y) of an id buffer lies on a triangle's edge: a 4-neighbour keeps another triangle.
bool onEdge(const std::vector<std::uint32_t>& ids, int width, int height, int x, int y) {
  const std::uint32_t id = ids[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    const int nx = x + dx[k], ny = y + dy[k];
    if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
    if (ids[static_cast<std::size_t>(ny) * static_cast<std::size_t>(width) + static_cast<std::size_t>(nx)] != id) return true;
  }
  return false;
}

struct Agreement {
  long covered = 0;          // pixels the rasterizer covers
  long otherTriangle = 0;    // pixels where the two keep different triangles
  long offEdge = 0;          // of those, pixels not on a triangle edge of the rasterizer's
  long sameTriangle = 0;     // pixels where both keep the same triangle
  long over = 0;             // of those, pixels whose colours differ by more than `bound` levels
  int maxDifference = 0;     // over the same-triangle pixels
};

Agreement agreementOf(const Scene& scene, const RenderSettings& s, int bound) {
  const FrameInputs frame = buildFrameInputs(scene, s);
  const auto raster = makeCpuRenderer(2);
  const auto traced = makeRayRenderer(2);
  const std::vector<std::uint32_t> a = *raster->render(scene, frame, {FrameOutput::TriangleIds}).triangleIds;
  const std::vector<std::uint32_t> b = *traced->render(scene, frame, {FrameOutput::TriangleIds}).triangleIds;
  const Image imageA = raster->render(scene, frame).image, imageB = traced->render(scene, frame).image;
  Agreement g;
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(x);
      g.covered += a[i] != 0;
      if (a[i] != b[i]) {
        ++g.otherTriangle;
        g.offEdge += onEdge(a, frame.width, frame.height, x, y) ? 0 : 1;
        continue;
      }
      ++g.sameTriangle;
      const int d = levelDifference(imageA.at(x, y), imageB.at(x, y));
      g.maxDifference = std::max(g.maxDifference, d);
      g.over += d > bound ? 1 : 0;
    }
  return g;
}

RenderSettings castingSettings() {
  RenderSettings s;
  s.width = 200, s.height = 150;
  s.ray.depth = 1;         // ray casting: no reflected or transmitted rays
  s.ray.spheres = false;   // the sphere's triangles, as the rasterizer draws them
  return s;
}

}  // namespace

TEST_CASE("ray casting: the course's window at unit distance puts t at the eye depth, and pixel centres where the rasterizer has them") {
  const Scene scene = makeDefaultScene();
  RenderSettings s;
  s.width = 64, s.height = 48;
  const FrameInputs frame = buildFrameInputs(scene, s);
  for (const glm::ivec2 pixel : {glm::ivec2(0, 0), glm::ivec2(63, 47), glm::ivec2(20, 31)}) {
    const ray::Ray r = ray::primaryRay(frame, pixel.x, pixel.y);
    const glm::vec3 P = r.origin + 3.0f * r.direction;
    const glm::vec4 eye = frame.eyeFromWorld * glm::vec4(P, 1.0f);
    CHECK(eye.z == doctest::Approx(3.0f).epsilon(1e-5));
    // Projected by PM and the viewport, the point lands on the pixel's centre.
    const glm::vec4 clip = frame.clipFromWorld * glm::vec4(P, 1.0f);
    const glm::vec4 window = frame.windowFromNdc * glm::vec4(glm::vec3(clip) / clip.w, 1.0f);
    CHECK(window.x == doctest::Approx(pixel.x + 0.5).epsilon(1e-4));
    CHECK(window.y == doctest::Approx(pixel.y + 0.5).epsilon(1e-4));
  }
}

TEST_CASE("the thin lens: every lens ray of a pixel passes where its pinhole ray reaches the eye depth in focus, and t stays the eye depth") {
  const Scene scene = makeDefaultScene();
  RenderSettings s;
  s.width = 64, s.height = 48;
  s.camera.aperture = 0.3f;
  s.camera.focusDistance = 4.0f;
  const FrameInputs frame = buildFrameInputs(scene, s);
  for (const glm::ivec2 pixel : {glm::ivec2(0, 0), glm::ivec2(63, 47), glm::ivec2(5, 40)})
    for (const glm::vec2 disk : {glm::vec2(1.0f, 0.0f), glm::vec2(-0.6f, 0.7f), glm::vec2(0.0f, -1.0f)}) {
      const ray::Ray pinhole = ray::primaryRay(frame, pixel.x, pixel.y), lens = ray::throughLens(frame, pinhole, disk, 4.0f);
      const glm::vec3 focus = pinhole.origin + 4.0f * pinhole.direction, through = lens.origin + 4.0f * lens.direction;
      CHECK(glm::length(through - focus) < 1e-5f * glm::length(focus));
      CHECK(glm::length(lens.origin - pinhole.origin) == doctest::Approx(0.3f * glm::length(disk)));
      CHECK((frame.eyeFromWorld * glm::vec4(lens.origin + 2.5f * lens.direction, 1.0f)).z == doctest::Approx(2.5f));
    }
}

TEST_CASE("ray casting agrees with the rasterizer: triangles differ only on edges, colours within a bound, shadows off") {
  RenderSettings s = castingSettings();
  s.shadows.enabled = false;
  for (const ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
    s.shading = mode;
    CAPTURE(mode);
    const Agreement g = agreementOf(makeDefaultScene(), s, 1);
    std::printf("ray casting vs rasterizer, default scene 200x150, %s, shadows off: %ld covered, %ld on another triangle (%ld off edges), "
                "%ld on the same: %ld over 1 level, max %d\n",
                kShadingModeNames[static_cast<std::size_t>(mode)].data(), g.covered, g.otherTriangle, g.offEdge, g.sameTriangle, g.over,
                g.maxDifference);
    CHECK(g.covered > 15000);
    CHECK(g.offEdge == 0);
    CHECK(g.otherTriangle < g.covered / 50);
    CHECK(g.over == 0);
  }
}

TEST_CASE("ray casting agrees with the rasterizer on culled and two-sided faces, textures and vertex colours") {
  // Back faces culled or lit two-sided by the same rule; texture levels of detail from ray differentials against the quads' derivatives.
  for (const char* name : {"double_sided.gltf", "vertex_colors.gltf", "textured_wraps.gltf", "mipmap_modes.gltf"})
    for (const bool cull : {true, false}) {
      CAPTURE(name);
      CAPTURE(cull);
      const Scene scene = loadScene(std::string(FACET_ASSETS) + "/scenes/" + name);
      RenderSettings s = castingSettings();
      s.shadows.enabled = false;
      s.cullBackFaces = cull;
      // 1 level: a hit's attributes are its vertices' weighted by barycentrics, the rasterizer's are planes of
      // a·(1/w) divided by the plane of 1/w; the same values, rounded differently.
      const Agreement g = agreementOf(scene, s, 1);
      std::printf("ray casting vs rasterizer, %s 200x150, culling %s: %ld covered, %ld on another triangle (%ld off edges), %ld on the same: "
                  "%ld over 1 level, max %d\n",
                  name, cull ? "on" : "off", g.covered, g.otherTriangle, g.offEdge, g.sameTriangle, g.over, g.maxDifference);
      CHECK(g.covered > 3000);
      CHECK(g.offEdge == 0);
      CHECK(g.over == 0);
    }
}

TEST_CASE("ray casting with shadow rays: the same image but where a shadow map's shadow differs from the exact one") {
  RenderSettings s = castingSettings();
  s.shadows.pcfRadius = 0;  // hard shadows, as shadow rays cast
  const Agreement g = agreementOf(makeDefaultScene(), s, 1);
  std::printf("ray casting vs rasterizer, default scene 200x150, phong, hard shadows: %ld covered, %ld on the same triangle: %ld over 1 level, max %d\n",
              g.covered, g.sameTriangle, g.over, g.maxDifference);
  CHECK(g.offEdge == 0);
  // The shadow maps' edges (aliasing, acne, the bias's peter-panning) are the only expected difference.
  CHECK(g.over > 0);
  CHECK(g.over < g.covered / 50);
}

TEST_CASE("optics: the law of reflection, Snell's law, the critical angle and Fresnel's reflectance at normal incidence") {
  const glm::vec3 N{0.0f, 0.0f, 1.0f};
  const float a = 40.0f * std::numbers::pi_v<float> / 180.0f, b = 45.0f * std::numbers::pi_v<float> / 180.0f;
  const glm::vec3 D40{std::sin(a), 0.0f, -std::cos(a)}, D45{std::sin(b), 0.0f, -std::cos(b)};
  CHECK(ray::reflected(D40, N).x == doctest::Approx(D40.x));
  CHECK(ray::reflected(D40, N).z == doctest::Approx(-D40.z));
  // Into glass: n1 sin θ1 = n2 sin θ2, and the ray stays a unit vector in the plane of incidence.
  const auto into = ray::refracted(D40, N, 1.0f, 1.5f);
  REQUIRE(into);
  CHECK(1.0f * std::sin(a) == doctest::Approx(1.5f * into->T.x));
  CHECK(glm::length(into->T) == doctest::Approx(1.0f));
  CHECK(into->T.y == 0.0f);
  // Out of glass, the critical angle is asin(1/1.5) = 41.8°: 40° leaves, 45° is totally reflected.
  const auto out = ray::refracted(D40, N, 1.5f, 1.0f);
  REQUIRE(out);
  CHECK(1.5f * std::sin(a) == doctest::Approx(out->T.x));
  CHECK_FALSE(ray::refracted(D45, N, 1.5f, 1.0f));
  CHECK(ray::fresnelSchlick(1.0f, 1.5f, 1.0f, 1.0f) == doctest::Approx(0.04f));
  CHECK(ray::fresnelSchlick(1.0f, 1.5f, 0.0f, 1.0f) == doctest::Approx(1.0f));
}

TEST_CASE("optics: the ray tracer's Fresnel takes (1 - c)^5 from std::pow, which rounds unlike shading=pbr's (x*x)*(x*x)*x") {
  // Both share pipeline/microfacet.h's F0 + (1 - F0)·x⁵; only x⁵ differs, and it must, bit for bit.
  const float r0 = (1.0f - 1.5f) / (1.0f + 1.5f), F0 = r0 * r0;
  int differ = 0;
  for (std::uint32_t k = 0; k <= (1u << 20); ++k) {
    const float c = static_cast<float>(k) * 0x1p-20f;
    const float pow5 = std::pow(1.0f - c, 5.0f);
    REQUIRE(ray::fresnelSchlick(1.0f, 1.5f, c, 1.0f) == schlickReflectance(F0, pow5));
    if (pow5 != schlickWeight(c)) ++differ;
  }
  CHECK(differ > 1000);  // of 2^20 + 1: (x²·x²)·x here would change the ray tracer's images
}

namespace {

// A scene lit by nothing (ambient 0, no light): what shows is emission, reflected and transmitted.
RenderSettings unlitParallel(int width, int height, float parallelWidth) {
  RenderSettings s;
  s.width = width, s.height = height;
  s.ambient = 0.0f;
  s.lightSource = Source::Manual;
  s.lights.clear();
  s.camera.source = Source::Manual;
  s.camera.projection = ProjectionKind::Parallel;
  s.camera.parallelWidth = parallelWidth;
  s.camera.eye = {0.0f, 0.0f, 5.0f};
  s.camera.reference = {0.0f, 0.0f, 0.0f};
  s.camera.up = {0.0f, 1.0f, 0.0f};
  s.camera.near = 0.1f;
  s.camera.far = 20.0f;
  s.background = glm::vec3(0.0f);
  return s;
}

int emissiveMaterial(Scene& scene, glm::vec3 color) {
  const int m = scene.addMaterial("emitter", glm::vec3(0.0f), 0.0f, 1.0f);
  scene.materials[static_cast<std::size_t>(m)].emissive = color;
  scene.materials[static_cast<std::size_t>(m)].doubleSided = true;
  return m;
}

// Linear value of an 8-bit sRGB level.
double linear(int level) {
  const double c = level / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace

TEST_CASE("recursive ray tracing: a tilted mirror shows what lies behind the camera where the law of reflection puts it") {
  constexpr float kDeg = std::numbers::pi_v<float> / 180.0f;
  Scene scene;
  const int mirror = scene.addMaterial("mirror", glm::vec3(1.0f), 1.0f, 0.0f);  // k_r = m·(1 - r)·O_s = 1
  // The plane z = 0 turned 22.5° about y: its normal (sin α, 0, cos α) sends the rays of the -z view to (sin 2α, 0, cos 2α).
  scene.addObject(makePlane(1), mirror, rotationY(22.5f * kDeg) * rotationX(std::numbers::pi_v<float> / 2.0f) * scaling(glm::vec3(3.0f)));
  // A red strip on the plane x = 3 between z = 1 and 2, facing the mirror, edge-on to the camera.
  scene.addObject(makePlane(1), emissiveMaterial(scene, {1.0f, 0.0f, 0.0f}),
                  translation({3.0f, 0.0f, 1.5f}) * rotationZ(std::numbers::pi_v<float> / 2.0f) * scaling({3.0f, 1.0f, 0.5f}));
  const RenderSettings s = unlitParallel(80, 8, 4.0f);
  const Image image = makeRayRenderer(2)->render(scene, buildFrameInputs(scene, s)).image;
  // A ray at x0 meets the mirror at z0 = -x0·tan α and x = 3 at z0 + (3 - x0): the strip for x0 in [1/(1 + tan α), 2/(1 + tan α)] = [0.707, 1.414],
  // pixel columns 54 to 67 (centres x = -2 + (px + 0.5)·4/80).
  for (int px = 0; px < 80; ++px) {
    CAPTURE(px);
    const bool red = px >= 54 && px <= 67;
    CHECK(image.at(px, 4).r == (red ? 255 : 0));
  }
}

TEST_CASE("recursive ray tracing: a glass slab displaces what is behind it by the slab formula, and Beer's law dims it") {
  constexpr float kDeg = std::numbers::pi_v<float> / 180.0f;
  constexpr float theta = 30.0f * kDeg, n = 1.5f;
  Scene scene;
  const int glass = scene.addMaterial("glass", glm::vec3(1.0f), 0.0f, 0.0f);
  scene.materials[static_cast<std::size_t>(glass)].transmission = 1.0f;
  scene.materials[static_cast<std::size_t>(glass)].ior = n;
  // A slab 1 thick, its faces' normals turned 30° about y from ±z; behind it, the half plane x < 0 glowing white.
  scene.addObject(makeCube(), glass, rotationY(theta) * scaling({6.0f, 6.0f, 0.5f}));
  scene.addObject(makePlane(1), emissiveMaterial(scene, glm::vec3(1.0f)),
                  translation({-5.0f, 0.0f, -3.0f}) * rotationX(std::numbers::pi_v<float> / 2.0f) * scaling({5.0f, 1.0f, 5.0f}));
  const RenderSettings s = unlitParallel(400, 4, 4.0f);  // 0.01 world units a pixel
  const Image image = makeRayRenderer(2)->render(scene, buildFrameInputs(scene, s)).image;
  // d = h·sin(θ1 - θ2)/cos θ2 across the ray, here along x, toward -x inside the slab: the edge at x = 0 shows at x = +d.
  const double theta2 = std::asin(std::sin(theta) / n);
  const double d = std::sin(theta - theta2) / std::cos(theta2);
  const double bright = linear(image.at(0, 2).r);
  REQUIRE(bright > 0.5);
  double edge = -1;  // where the level falls through half the bright one, between pixel centres
  for (int px = 1; px < 400 && edge < 0; ++px) {
    const double a = linear(image.at(px - 1, 2).r), b = linear(image.at(px, 2).r);
    if (a >= 0.5 * bright && b < 0.5 * bright) edge = -2.0 + (px - 0.5 + (a - 0.5 * bright) / (a - b)) * 0.01;
  }
  std::printf("glass slab, 30 degrees, n = 1.5, 1 thick: the edge moves %.4f, the slab formula says %.4f\n", edge, d);
  CHECK(std::abs(edge - d) < 0.01);  // within a pixel

  // Straight on, a slab that keeps half the light per unit of distance: (1 - F0)² through two faces, times e^(-σ·1) = 0.5.
  scene.materials[static_cast<std::size_t>(glass)].attenuationColor = glm::vec3(0.5f);
  scene.materials[static_cast<std::size_t>(glass)].attenuationDistance = 1.0f;
  scene.instances[0].worldFromModel = scaling({6.0f, 6.0f, 0.5f});
  scene.identity.renew();
  const Image dimmed = makeRayRenderer(2)->render(scene, buildFrameInputs(scene, s)).image;
  const double F0 = 0.04;
  CHECK(linear(dimmed.at(50, 2).r) == doctest::Approx((1 - F0) * (1 - F0) * 0.5).epsilon(0.01));
}

TEST_CASE("recursive ray tracing: ray.depth and ray.minContribution stop the tree between two facing mirrors") {
  Scene scene;
  const int mirror = scene.addMaterial("half mirror", glm::vec3(1.0f), 1.0f, 0.0f);
  // Two mirrors facing each other across the view: z = -1 facing +z and z = 4 facing -z, the camera between them.
  scene.addObject(makePlane(1), mirror, translation({0.0f, 0.0f, -1.0f}) * rotationX(std::numbers::pi_v<float> / 2.0f) * scaling(glm::vec3(5.0f)));
  scene.addObject(makePlane(1), mirror, translation({0.0f, 0.0f, 4.0f}) * rotationX(-std::numbers::pi_v<float> / 2.0f) * scaling(glm::vec3(5.0f)));
  RenderSettings s = unlitParallel(4, 4, 2.0f);
  s.camera.eye = {0.0f, 0.0f, 2.0f};
  s.camera.near = 0.01f;
  const auto reflectedRays = [&](int depth, float minContribution, float reflectivity) {
    s.ray.depth = depth;
    s.ray.minContribution = minContribution;
    s.material.reflectivity = reflectivity;
    const RenderResult result = makeRayRenderer(1)->render(scene, buildFrameInputs(scene, s));
    const std::string& tree = result.notes.back();
    CAPTURE(tree);
    const std::size_t at = tree.find(" reflected");
    REQUIRE(at != std::string::npos);
    return std::stol(tree.substr(tree.rfind(' ', at - 1) + 1, at));
  };
  // Every primary ray hits a mirror; each level below it reflects once more.
  CHECK(reflectedRays(1, 0.0f, 1.0f) == 0);
  CHECK(reflectedRays(3, 0.0f, 1.0f) == 16 * 2);
  CHECK(reflectedRays(6, 0.0f, 1.0f) == 16 * 5);
  // k_r = 0.5: weights 0.5, 0.25, 0.125 pass 0.1; 0.0625 does not.
  CHECK(reflectedRays(16, 0.1f, 0.5f) == 16 * 3);
}

TEST_CASE("stochastic ray tracing: the same seed gives the same image whatever the threads, another seed another image") {
  const Scene scene = makeCornellBox();
  RenderSettings s;
  s.width = 64, s.height = 48;
  s.ray.samples = 4;
  s.camera.aperture = 0.05f;
  s.ray.gloss = true;
  const FrameInputs frame = buildFrameInputs(scene, s);
  const Image one = makeRayRenderer(1)->render(scene, frame).image, two = makeRayRenderer(2)->render(scene, frame).image;
  CHECK(one == two);
  s.ray.seed = 2;
  CHECK(makeRayRenderer(2)->render(scene, buildFrameInputs(scene, s)).image != one);
}

TEST_CASE("stochastic ray tracing: an area light's penumbra spans what similar triangles say") {
  // A light of radius r at height H over the floor; an opaque half plane x < 0 at height h between them.
  constexpr float H = 4.0f, h = 2.0f, r = 0.5f;
  Scene scene;
  const int grey = scene.addMaterial("grey", glm::vec3(0.5f), 0.0f, 1.0f);
  scene.addObject(makePlane(1), grey, scaling(glm::vec3(10.0f)));                                              // the floor
  scene.addObject(makePlane(1), grey, translation({-5.0f, h, 0.0f}) * scaling({5.0f, 1.0f, 5.0f}));          // the occluder
  RenderSettings s;
  s.width = 8, s.height = 8;
  s.lightSource = Source::Manual;
  Light light;
  light.position = {0.0f, H, 0.0f};
  light.radius = r;
  s.lights = {light};
  const FrameInputs frame = buildFrameInputs(scene, s);
  ThreadPool pool(1);
  const ray::TracedScene traced(scene, frame, true, pool);
  const ray::RayTracer tracer(traced, frame);
  // The fraction of the light's disk a floor point at x sees, over 4096 paths.
  const auto lit = [&](float x) {
    ray::RayStatistics statistics;
    double sum = 0;
    for (std::uint32_t k = 0; k < 4096; ++k) {
      ray::PathSampler sampler(1, 0, k);
      sum += tracer.shadowFactor(frame.lights[0], {x, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, sampler, statistics);
    }
    return sum / 4096;
  };
  // The penumbra on the floor: |x| < r·h/(H - h) = 0.5; half the disk seen under the edge.
  const float half = r * h / (H - h);
  CHECK(lit(0.0f) == doctest::Approx(0.5).epsilon(0.05));
  CHECK(lit(-1.05f * half) == 0.0);
  CHECK(lit(1.05f * half) == 1.0);
  CHECK(lit(-0.5f * half) < lit(0.0f));
  CHECK(lit(0.5f * half) > lit(0.0f));
}

TEST_CASE("stochastic ray tracing: the thin lens keeps the plane in focus as the pinhole sees it, and blurs what is not") {
  Scene scene;
  const int white = emissiveMaterial(scene, glm::vec3(1.0f));
  // Two glowing half planes facing the camera: x < 0 at the eye depth in focus (5), x > 0.5 at twice it.
  scene.addObject(makePlane(1), white, translation({-2.0f, 0.0f, 0.0f}) * rotationX(std::numbers::pi_v<float> / 2.0f) * scaling({2.0f, 1.0f, 2.0f}));
  scene.addObject(makePlane(1), white, translation({4.0f, 0.0f, -5.0f}) * rotationX(std::numbers::pi_v<float> / 2.0f) * scaling({3.5f, 1.0f, 4.0f}));
  RenderSettings s = unlitParallel(200, 4, 4.0f);
  s.camera.projection = ProjectionKind::Perspective;
  s.camera.halfAngleDeg = 30.0f;
  s.ray.samples = 1;
  const Image pinhole = makeRayRenderer(2)->render(scene, buildFrameInputs(scene, s)).image;
  s.camera.aperture = 0.2f;
  s.camera.focusDistance = 5.0f;
  s.ray.samples = 64;
  const Image lens = makeRayRenderer(2)->render(scene, buildFrameInputs(scene, s)).image;
  // In focus, every path of a pixel meets the plane where its pinhole ray does: the left edge is the pinhole's.
  for (int px = 60; px < 100; ++px) CHECK(lens.at(px, 2).r == pinhole.at(px, 2).r);
  // Out of focus, at depth 10: the far plane's edge at x = 0.5 spreads over a circle of confusion of radius
  // A·(z - f)/f = 0.2 world units there, 0.2/(10·tan 30°)·100 = 3.5 pixels: graded pixels, not a step.
  int graded = 0;
  for (int px = 100; px < 200; ++px) graded += lens.at(px, 2).r > 10 && lens.at(px, 2).r < 245 ? 1 : 0;
  int gradedPinhole = 0;
  for (int px = 100; px < 200; ++px) gradedPinhole += pinhole.at(px, 2).r > 10 && pinhole.at(px, 2).r < 245 ? 1 : 0;
  CHECK(gradedPinhole == 0);
  CHECK(graded >= 4);
  CHECK(graded <= 9);
}

TEST_CASE("stochastic ray tracing: motion blur spreads a moving edge over the distance it travels while the shutter is open") {
  // A glowing half plane x < 0 moving along +x at 1 unit a second (a glTF translation channel).
  Scene scene;
  scene.addObject(makePlane(1), emissiveMaterial(scene, glm::vec3(1.0f)),
                  translation({-3.0f, 0.0f, 0.0f}) * rotationX(std::numbers::pi_v<float> / 2.0f) * scaling({3.0f, 1.0f, 3.0f}));
  AnimatedNode node;
  node.translation = {-3.0f, 0.0f, 0.0f};
  node.rotation = glm::angleAxis(std::numbers::pi_v<float> / 2.0f, glm::vec3(1.0f, 0.0f, 0.0f));
  node.scale = {3.0f, 1.0f, 3.0f};
  node.local = scene.instances[0].worldFromModel;
  scene.animation.nodes = {node};
  scene.animation.instanceNodes = {0};
  AnimationChannel moving;
  moving.path = AnimatedPath::Translation;
  moving.times = {0.0f, 10.0f};
  moving.values = {glm::vec4(-3.0f, 0.0f, 0.0f, 0.0f), glm::vec4(7.0f, 0.0f, 0.0f, 0.0f)};
  scene.animation.channels = {moving};
  RenderSettings s = unlitParallel(200, 4, 4.0f);  // 0.02 world units a pixel, x = -2 + (px + 0.5)·0.02
  s.ray.samples = 64;
  const auto level = [](const Image& image, float x) { return linear(image.at(static_cast<int>((x + 2.0f) / 0.02f), 2).r); };
  const Image still = makeRayRenderer(2)->render(scene, buildFrameInputs(scene, s)).image;
  CHECK(level(still, -0.05f) == 1.0);
  CHECK(level(still, 0.05f) == 0.0);
  s.camera.shutter = 0.5f;
  const Image blurred = makeRayRenderer(2)->render(scene, buildFrameInputs(scene, s)).image;
  // Open from 0 to 0.5 s, the edge sweeps x from 0 to 0.5: a point there is lit the time the edge is past it.
  CHECK(level(blurred, -0.05f) == doctest::Approx(1.0).epsilon(0.01));
  CHECK(level(blurred, 0.125f) == doctest::Approx(0.75).epsilon(0.1));
  CHECK(level(blurred, 0.25f) == doctest::Approx(0.5).epsilon(0.1));
  CHECK(level(blurred, 0.375f) == doctest::Approx(0.25).epsilon(0.15));
  CHECK(level(blurred, 0.55f) == 0.0);
}
