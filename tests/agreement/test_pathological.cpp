// Geometry that breaks naive rasterizers, through both backends: each case
// renders in both, the two agree (the same triangle at every pixel, every
// byte equal), and what must not be drawn is not drawn.
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <doctest/doctest.h>

#include "compare/backend_agreement.h"
#include "compare/image_diff.h"
#include "cpu/cpu_renderer.h"
#include "image/srgb.h"
#include "gl/gl_renderer.h"
#include "math/transforms.h"
#include "pipeline/frame_inputs.h"
#include "scene/primitives.h"

using namespace facet;

namespace {

constexpr int kSize = 96;

struct Renders {
  Image gl, cpu;
  std::vector<std::uint32_t> glTriangles, cpuTriangles;
  Rgba8 background{};
};

Renderer& glRenderer() {
  static std::unique_ptr<Renderer> renderer = makeGlRenderer(GlContextKind::OsMesa);  // one context for the whole test run
  return *renderer;
}

Renders renderBoth(const Scene& scene, const RenderSettings& settings) {
  const FrameInputs frame = buildFrameInputs(scene, settings);
  Renders r;
  r.gl = glRenderer().render(scene, frame).image;
  const auto cpu = makeCpuRenderer(2);
  r.cpu = cpu->render(scene, frame).image;
  r.glTriangles = *glRenderer().render(scene, frame, {FrameOutput::TriangleIds}).triangleIds;
  r.cpuTriangles = *cpu->render(scene, frame, {FrameOutput::TriangleIds}).triangleIds;
  r.background = encodePixel(frame.background);
  return r;
}

long drawnPixels(const Image& image, Rgba8 background) {
  long count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) count += !(image.at(x, y) == background);
  return count;
}

void checkAgreement(const Renders& r) {
  long triangles = 0;
  for (std::size_t i = 0; i < r.glTriangles.size(); ++i) triangles += r.glTriangles[i] != r.cpuTriangles[i];
  CHECK(r.glTriangles.size() == r.cpuTriangles.size());
  CHECK(triangles == 0);
  CHECK(compareImages(r.cpu, r.gl, backendAgreement()).status == DiffStatus::Pass);
}

Scene oneMesh(Mesh mesh) {
  Scene scene;
  if (mesh.normals.size() != mesh.positions.size()) mesh.normals.assign(mesh.positions.size(), glm::vec3(0, 0, 1));
  mesh.material = 0;
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back({0, glm::mat4(1.0f)});
  Material m;
  m.baseColor = {0.8f, 0.6f, 0.3f, 1.0f};
  m.metallic = 0.0f;
  scene.materials.push_back(m);
  return scene;
}

RenderSettings frontView() {
  RenderSettings s;
  s.width = s.height = kSize;
  s.camera.source = Source::Manual;
  s.camera.eye = {0, 0, 5};
  s.camera.reference = {0, 0, 0};
  s.camera.near = 0.5f;
  s.camera.far = 50.0f;
  s.lightSource = Source::Manual;
  Light light;
  light.position = {1, 2, 4};
  light.castsShadow = false;
  s.lights = {light};
  s.cullBackFaces = false;
  return s;
}

}  // namespace

TEST_CASE("huge coordinates: a triangle reaching 1e7 away is clipped, drawn, and agrees") {
  Mesh mesh;
  mesh.positions = {{-1e7f, -1e7f, 0}, {1e7f, -1e7f, 0}, {0, 1e7f, 0}, {-0.5f, -0.5f, 1}, {0.5f, -0.5f, 1}, {0, 0.5f, 1}};
  mesh.indices = {0, 1, 2, 3, 4, 5};
  const Renders r = renderBoth(oneMesh(mesh), frontView());
  CHECK(drawnPixels(r.cpu, r.background) == kSize * kSize);  // the huge triangle fills the view
  checkAgreement(r);
}

TEST_CASE("zero-area and sliver triangles: nothing for the degenerate ones, the same pixels for slivers") {
  Mesh degenerate;
  degenerate.positions = {{-1, -1, 0}, {0, 0, 0}, {1, 1, 0}, {0.3f, 0.2f, 0}, {0.3f, 0.2f, 0}, {0.9f, -0.4f, 0}};
  degenerate.indices = {0, 1, 2, 3, 4, 5};
  const Renders none = renderBoth(oneMesh(degenerate), frontView());
  CHECK(drawnPixels(none.cpu, none.background) == 0);
  CHECK(drawnPixels(none.gl, none.background) == 0);

  Mesh slivers;
  for (int i = 0; i < 40; ++i) {  // long needles a hair wide, at many angles
    const float a = 0.157f * static_cast<float>(i);
    const glm::vec3 d{std::cos(a), std::sin(a), 0}, n{-std::sin(a) * 0.002f, std::cos(a) * 0.002f, 0};
    const auto base = static_cast<std::uint32_t>(slivers.positions.size());
    slivers.positions.insert(slivers.positions.end(), {-1.8f * d, 1.8f * d, 1.8f * d + n});
    slivers.indices.insert(slivers.indices.end(), {base, base + 1, base + 2});
  }
  const Renders r = renderBoth(oneMesh(slivers), frontView());
  CHECK(drawnPixels(r.cpu, r.background) > 0);
  checkAgreement(r);
}

TEST_CASE("NaN and infinite vertices: their triangles are dropped, the rest is drawn") {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  Mesh good;
  good.positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  good.indices = {0, 1, 2};
  Mesh bad = good;
  bad.positions.insert(bad.positions.end(), {{nan, 0, 0}, {1, 1, 0}, {-1, 1, 0}, {inf, -inf, 0}, {0.5f, 0.5f, 0}, {0.2f, 0.9f, 0}});
  bad.indices.insert(bad.indices.end(), {3, 4, 5, 6, 7, 8});
  const Renders withBad = renderBoth(oneMesh(bad), frontView());
  const Renders only = renderBoth(oneMesh(good), frontView());
  CHECK(drawnPixels(only.cpu, only.background) > 500);
  CHECK(withBad.cpu == only.cpu);
  CHECK(withBad.gl == only.gl);
}

TEST_CASE("triangles wholly behind the eye (w <= 0) draw nothing") {
  Mesh behind;
  behind.positions = {{-1, -1, 8}, {1, -1, 8}, {0, 1, 8}, {-3, -3, 5.2f}, {3, -3, 5.2f}, {0, 3, 5.2f}};
  behind.indices = {0, 1, 2, 3, 4, 5};
  const Renders r = renderBoth(oneMesh(behind), frontView());
  CHECK(drawnPixels(r.cpu, r.background) == 0);
  CHECK(drawnPixels(r.gl, r.background) == 0);
}

TEST_CASE("camera inside a mesh: culled away with culling on, seen from inside with two-sided lighting when off") {
  Scene scene = oneMesh(makeSphere(16));
  scene.instances[0].worldFromModel = translation({0, 0, 5}) * scaling(glm::vec3(2.0f));  // around the eye
  RenderSettings s = frontView();
  s.cullBackFaces = true;
  const Renders culled = renderBoth(scene, s);
  CHECK(drawnPixels(culled.cpu, culled.background) == 0);
  CHECK(drawnPixels(culled.gl, culled.background) == 0);
  s.cullBackFaces = false;
  s.lights[0].position = {0, 0, 5};  // a light in there too
  const Renders inside = renderBoth(scene, s);
  CHECK(drawnPixels(inside.cpu, inside.background) == kSize * kSize);
  checkAgreement(inside);
}

TEST_CASE("light inside a closed mesh with shadows: the mesh shadows the ground outside it") {
  Scene scene = oneMesh(makeCube());
  scene.meshes.push_back(makePlane(4));
  scene.meshes.back().material = 0;
  scene.instances.push_back({1, translation({0, -1.5f, 0}) * scaling(glm::vec3(6.0f))});
  RenderSettings s = frontView();
  s.camera.eye = {0, 4, 8};
  s.cullBackFaces = true;
  s.lights[0].position = {0, 0, 0};  // inside the cube
  s.lights[0].castsShadow = true;
  s.shadows.enabled = true;
  s.shadows.mapSize = 256;
  const Renders shadowed = renderBoth(scene, s);
  checkAgreement(shadowed);
  s.shadows.enabled = false;
  const Renders lit = renderBoth(scene, s);
  // The ground in front of the cube (lower image rows) is lit only without shadows.
  CHECK(shadowed.cpu.at(kSize / 2, 8).r + 20 < lit.cpu.at(kSize / 2, 8).r);
  CHECK(shadowed.gl.at(kSize / 2, 8).r + 20 < lit.gl.at(kSize / 2, 8).r);
}
