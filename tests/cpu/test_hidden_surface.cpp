// The course's other hidden-surface algorithms (renderer/PIPELINE.md,
// "Hidden-surface removal"): the painter's order, what the
// painter's algorithm draws where it fails, and the scanline z-buffer, which
// must keep what the z-buffer keeps at every pixel, also where depths tie.
#include <random>
#include <string>

#include <doctest/doctest.h>

#include "cpu/cpu_renderer.h"
#include "cpu/scanline_zbuffer.h"
#include "cpu_test_scenes.h"
#include "image/mipmap.h"
#include "math/transforms.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/painters_order.h"
#include "scene/default_scene.h"

using namespace facet;

namespace {

// A horizontal square of side 2·half at height y, centred on (cx, cz): two triangles facing +y.
void addSquare(Mesh& m, float y, float cx, float cz, float half) {
  const auto first = static_cast<std::uint32_t>(m.positions.size());
  for (const glm::vec2 c : {glm::vec2(-1, 1), glm::vec2(1, 1), glm::vec2(1, -1), glm::vec2(-1, -1)}) {
    m.positions.push_back({cx + half * c.x, y, cz + half * c.y});
    m.normals.push_back({0, 1, 0});
  }
  m.indices.insert(m.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
}

Scene sceneOf(Mesh mesh) {
  Scene scene;
  scene.addObject(std::move(mesh), scene.addMaterial("grey", {0.6f, 0.6f, 0.6f}, 0.0f, 0.5f), glm::mat4(1.0f));
  return scene;
}

std::vector<std::uint32_t> idsOf(const Scene& scene, RenderSettings s, HiddenSurface hsr, int threads = 2) {
  s.hsr = hsr;
  return *makeCpuRenderer(threads)->render(scene, buildFrameInputs(scene, s), {FrameOutput::TriangleIds}).triangleIds;
}

// A triangle soup in the top-down view's box: random triangles at random
// heights and slopes (they intersect), exact duplicates (equal depths), and
// coplanar pieces of earlier triangles (depths equal up to rounding).
Scene soup(unsigned seed, int n) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> xz(-2.2f, 2.2f), height(0.0f, 3.0f), unit(0.0f, 1.0f);
  Mesh m;
  const auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const auto first = static_cast<std::uint32_t>(m.positions.size());
    for (const glm::vec3& p : {a, b, c}) {
      m.positions.push_back(p);
      m.normals.push_back({0, 1, 0});
    }
    m.indices.insert(m.indices.end(), {first, first + 1, first + 2});
  };
  for (int i = 0; i < n; ++i) {
    const glm::vec3 a{xz(random), height(random), xz(random)}, b{xz(random), height(random), xz(random)}, c{xz(random), height(random), xz(random)};
    add(a, b, c);
    const float r = unit(random);
    if (r < 0.25f) add(a, b, c);  // the same triangle again: the z-buffer keeps the first
    else if (r < 0.5f) {          // a piece of the same plane
      const auto mix = [&](float u, float v) { return a + u * (b - a) + v * (c - a); };
      add(mix(0.1f, 0.1f), mix(0.9f * unit(random), 0.05f), mix(0.05f, 0.9f * unit(random)));
    }
  }
  return sceneOf(std::move(m));
}

long differing(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
  long n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
  return n;
}

long covered(const std::vector<std::uint32_t>& ids) {
  long n = 0;
  for (const std::uint32_t id : ids) n += id != 0;
  return n;
}

}  // namespace

TEST_CASE("painter's order: farthest eye depth first, ties in the triangle list's order") {
  Mesh m;
  addSquare(m, 1.0f, -0.5f, 0.0f, 1.0f);  // triangles 0, 1: nearer the eye at y = 10
  addSquare(m, 0.0f, 0.5f, 0.0f, 1.0f);   // triangles 2, 3: the farthest
  addSquare(m, 2.0f, 0.0f, 0.5f, 0.5f);   // triangles 4, 5: the nearest
  const Scene scene = sceneOf(std::move(m));
  const FrameInputs frame = buildFrameInputs(scene, test::topDownSettings(64));
  CHECK(paintersOrder(scene, frame) == std::vector<std::uint32_t>{2, 3, 0, 1, 4, 5});
  RenderSettings s = test::topDownSettings(64);
  s.hsr = HiddenSurface::Painter;
  CHECK(buildFrameInputs(scene, s).paintersOrder == std::vector<std::uint32_t>{2, 3, 0, 1, 4, 5});
  CHECK(buildFrameInputs(scene, test::topDownSettings(64)).paintersOrder.empty());  // only the painter's frames sort
}

TEST_CASE("painter's algorithm: right where the order is, wrong where polygons intersect") {
  // Stacked squares listed nearest first: the z-buffer and the painter agree at every pixel.
  Mesh stacked;
  addSquare(stacked, 2.0f, 0.0f, 0.0f, 0.6f);
  addSquare(stacked, 1.0f, 0.3f, 0.3f, 0.9f);
  addSquare(stacked, 0.0f, -0.3f, 0.0f, 1.5f);
  const Scene ordered = sceneOf(std::move(stacked));
  const RenderSettings s = test::topDownSettings(96);
  const auto zbuffer = idsOf(ordered, s, HiddenSurface::ZBuffer), painter = idsOf(ordered, s, HiddenSurface::Painter);
  CHECK(covered(zbuffer) > 4000);
  CHECK(differing(zbuffer, painter) == 0);

  // Two squares that cross: each is nearer the eye over half of the overlap.
  // The one whose far edge is farther is painted first and loses the whole overlap.
  Mesh crossing;
  for (const float tilt : {0.8f, -0.6f}) {
    const auto first = static_cast<std::uint32_t>(crossing.positions.size());
    for (const glm::vec2 c : {glm::vec2(-1, 1), glm::vec2(1, 1), glm::vec2(1, -1), glm::vec2(-1, -1)}) {
      crossing.positions.push_back({1.5f * c.x, 1.0f + tilt * c.x, 1.5f * c.y});
      crossing.normals.push_back({0, 1, 0});
    }
    crossing.indices.insert(crossing.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  }
  const Scene x = sceneOf(std::move(crossing));
  const auto zx = idsOf(x, s, HiddenSurface::ZBuffer), px = idsOf(x, s, HiddenSurface::Painter);
  const long wrong = differing(zx, px);
  CAPTURE(wrong);
  CHECK(wrong > 1000);               // half the overlap shows the far square
  CHECK(wrong < covered(zx) / 2 + 1);
  // Every pixel the painter got wrong shows the square it painted last.
  const std::vector<std::uint32_t> order = buildFrameInputs(x, [&] {
                                             RenderSettings p = s;
                                             p.hsr = HiddenSurface::Painter;
                                             return p;
                                           }()).paintersOrder;
  const std::uint32_t lastSquare = order.back() / 2;
  for (std::size_t i = 0; i < zx.size(); ++i)
    if (zx[i] != px[i]) REQUIRE((px[i] - 1) / 2 == lastSquare);
}

TEST_CASE("scanline z-buffer: the z-buffer's triangle at every pixel of triangle soups with ties, any thread count") {
  RenderSettings top = test::topDownSettings(157);
  top.cullBackFaces = false;
  RenderSettings perspective = top;
  perspective.camera.projection = ProjectionKind::Perspective;
  perspective.camera.eye = {0.7f, 6.0f, 4.5f};
  perspective.camera.up = {0, 1, 0};
  perspective.width = 203;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const Scene scene = soup(seed, 60);
    for (const RenderSettings& s : {top, perspective}) {
      CAPTURE(seed);
      CAPTURE(s.width);
      const auto zbuffer = idsOf(scene, s, HiddenSurface::ZBuffer);
      CHECK(covered(zbuffer) > s.width * s.height / 4);
      for (const int threads : {1, 3}) {
        CAPTURE(threads);
        CHECK(differing(idsOf(scene, s, HiddenSurface::Scanline, threads), zbuffer) == 0);
      }
    }
  }
}

TEST_CASE("scanline z-buffer: the default scene's image, byte for byte, and depth memory proportional to the width") {
  const Scene scene = makeDefaultScene();
  RenderSettings s;
  s.width = 211;
  s.height = 97;
  s.shadows.mapSize = 256;
  const Image zbuffer = test::renderCpu(scene, s);
  s.hsr = HiddenSurface::Scanline;
  const Image scanline = test::renderCpu(scene, s);
  long differ = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) differ += !(zbuffer.at(x, y) == scanline.at(x, y));
  CHECK(differ == 0);
  CHECK(cpu::scanlineDepthBytes(1920, 2) == 2 * cpu::scanlineDepthBytes(1920, 1));
  CHECK(cpu::scanlineDepthBytes(3840, 1) == 2 * cpu::scanlineDepthBytes(1920, 1));
  CHECK(cpu::scanlineDepthBytes(1920, 1) < 1920u * 1080u * sizeof(float) / 100);  // a row, not a frame
}

TEST_CASE("scanline z-buffer: an alpha-masked texture without vertex colours, its vertices the frame's last, as the z-buffer draws it") {
  // The mask reads the texture coordinates alone: the frame packs no more, and the scanline's set-up must
  // read no more either (its last vertex ends the packed buffer: under AddressSanitizer, a read past it fails).
  Scene scene = test::groundScene(1, {0.5f, 0.5f, 0.5f});
  Texture halves;
  halves.image = Image(2, 1, Rgba8{230, 20, 20, 255});
  halves.image.at(0, 0) = Rgba8{230, 20, 20, 0};  // s < 0.5: cut away
  halves.sampler.mag = MagFilter::Nearest;
  halves.sampler.min = MinFilter::Nearest;
  halves.mips = mipLevels(halves.image, halves.encoding);
  scene.textures.push_back(halves);
  Mesh quad;
  quad.positions = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}};
  quad.normals.assign(4, {0, 1, 0});
  quad.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  const int masked = scene.addMaterial("masked", {1, 1, 1}, 0.0f, 1.0f);
  Material& m = scene.materials[static_cast<std::size_t>(masked)];
  m.alphaMode = AlphaMode::Mask;
  m.doubleSided = true;
  m.baseColorTexture = static_cast<int>(scene.textures.size() - 1);
  scene.addObject(quad, masked, translation({0.0f, 0.5f, 0.0f}));
  RenderSettings s = test::topDownSettings(96);
  s.shading = ShadingMode::Phong;
  const Image zbuffer = test::renderCpu(scene, s);
  s.hsr = HiddenSurface::Scanline;
  const Image scanline = test::renderCpu(scene, s);
  long red = 0, differ = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const Rgba8 p = scanline.at(x, y);
      red += p.r > 2 * p.g + 20;
      differ += !(p == zbuffer.at(x, y));
    }
  CHECK(differ == 0);
  // The kept half of the quad is an eighth of the view; the cut half shows the ground.
  CHECK(red > s.width * s.height / 16);
  CHECK(red < s.width * s.height * 3 / 16);
}
