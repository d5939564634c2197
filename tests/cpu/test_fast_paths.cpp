// The CPU renderer's fast paths give the same bits as the plain ones: the
// sRGB bucket table against the thresholds' binary search (and those against
// the IEC formula), the four-lane Phong batch against illuminate<float>,
// thread counts and reused buffers (shadow maps cleared tile by tile)
// against a fresh renderer.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <deque>
#include <vector>

#include <doctest/doctest.h>

#include "common/error.h"
#include "shading/blending.h"
#include "cpu/cpu_renderer.h"
#include "cpu/depth_rows.h"
#include "common/lane_width.h"
#include "shading/lighting.h"
#include "cpu/phong_batch.h"
#include "shading/resolve.h"
#include "common/thread_pool.h"
#include "shading/srgb_table.h"
#include "image/color_buffer.h"
#include "image/srgb.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/light_frustum.h"
#include "scene/default_scene.h"
#include "math/transforms.h"
#include "../skipped.h"

using namespace facet;

namespace {

// The lane widths of `wanted` this CPU runs (lane_width.h). Each one it
// lacks is reported as skipped: its code is built, and a host without
// AVX2 or AVX-512 must not show its checks as passed.
std::vector<int> lanesHere(std::initializer_list<int> wanted) {
  std::vector<int> here;
  for (const int lanes : wanted) {
    if (lanes <= widestLanes()) here.push_back(lanes);
    else test::skipped(std::to_string(lanes) + " lanes: this CPU runs at most " + std::to_string(widestLanes()));
  }
  return here;
}

unsigned formula(float linear) { return levelBySearch(linear); }

// IEC 61966-2-1 written out here, in double: the 8-bit level of c in [0, 1].
unsigned iecLevel(float c) {
  const double x = c;
  return static_cast<unsigned>(std::floor(255.0 * (x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055) + 0.5));
}

Image render(Renderer& renderer, const Scene& scene, const RenderSettings& settings) {
  return renderer.render(scene, buildFrameInputs(scene, settings)).image;
}

}  // namespace

TEST_CASE("sRGB thresholds: each is the first float of its level by the IEC formula, and every byte decodes to the formula's value") {
  const SrgbTables& tables = srgbTables();
  for (unsigned k = 1; k < 256; ++k) {
    CAPTURE(k);
    const float t = tables.thresholds[k];
    CHECK(iecLevel(t) == k);
    CHECK(iecLevel(std::nextafter(t, 0.0f)) == k - 1);
    CHECK(levelBySearch(t) == k);
    CHECK(levelBySearch(std::nextafter(t, 0.0f)) == k - 1);
  }
  for (unsigned v = 0; v < 256; ++v) {
    const double c = v / 255.0;
    CHECK(tables.decoded[v] == static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4)));
  }
  CHECK(levelBySearch(-1.0f) == 0);
  CHECK(levelBySearch(std::numeric_limits<float>::quiet_NaN()) == 0);
  CHECK(levelBySearch(2.0f) == 255);
}

TEST_CASE("sRGB buckets: encodeLevel equals the thresholds' binary search for every float from 2^-9 to 1, and at the edges") {
  const std::uint32_t first = std::bit_cast<std::uint32_t>(0x1p-9f), last = std::bit_cast<std::uint32_t>(1.0f);
  std::uint64_t mismatches = 0;
  for (std::uint32_t bits = first; bits <= last; ++bits) {
    const float c = std::bit_cast<float>(bits);
    mismatches += encodeLevel(c) != formula(c);
  }
  CHECK(mismatches == 0);
  // Below 2^-9 (< 0.0031308) the formula is 12.92·c: a product, non-decreasing, so the thresholds hold; spot-check it.
  for (std::uint32_t bits = 0; bits < first; bits += 997) CHECK(encodeLevel(std::bit_cast<float>(bits)) == formula(std::bit_cast<float>(bits)));
  for (float c : {0.0f, -0.0f, -1.0f, 1.0f, 2.0f, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                  std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::denorm_min()})
    CHECK(encodeLevel(c) == formula(c));
  // encodePixel4 (the clamp, bucket and alpha level on four lanes) against encodePixel, over a stride of all float bit patterns.
  std::uint64_t mismatches4 = 0;
  const SrgbTables& tables = srgbTables();
  for (std::uint64_t bits = 0; bits <= 0xffffffffu; bits += 4 * 4099) {
    float four[4];
    for (int k = 0; k < 4; ++k) four[k] = std::bit_cast<float>(static_cast<std::uint32_t>(bits + static_cast<std::uint64_t>(k) * 4099));
    const Rgba8 got = encodePixel4(tables, four), want = encodePixel(glm::vec4(four[0], four[1], four[2], four[3]));
    mismatches4 += got.r != want.r || got.g != want.g || got.b != want.b || got.a != want.a;
  }
  CHECK(mismatches4 == 0);
}

TEST_CASE("Resolve: the CPU's four-channel resolve gives encodePixel's bytes for every pixel, alpha by its own linear rule") {
  std::mt19937 random(174);
  std::uniform_real_distribution<float> value(-0.25f, 1.25f);
  constexpr int kWidth = 67, kHeight = 13;  // rows split unevenly across the workers
  ColorBuffer buffer(kWidth, kHeight, glm::vec4(0.0f));
  const float specials[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), -0.0f, 0.5f, 1.0f, 127.5f / 255.0f};
  for (int i = 0; i < kWidth * kHeight; ++i) {
    glm::vec4& c = buffer.data()[i];
    c = {value(random), value(random), value(random), value(random)};
    if (i % 7 == 0) c[i % 4] = specials[static_cast<std::size_t>(i / 7) % std::size(specials)];
  }
  ThreadPool pool(3);
  Image image;
  resolve(pool, buffer, Blending::Straight, 1, 1, image);
  REQUIRE(image.width() == kWidth);
  REQUIRE(image.height() == kHeight);
  int differing = 0;
  std::set<int> alphas;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    differing += image.data()[i] == encodePixel(buffer.data()[i]) ? 0 : 1;
    alphas.insert(image.data()[i].a);
  }
  CHECK(differing == 0);
  CHECK(alphas.size() > 200);  // alpha is carried, not set to 255
  // floor(255·a + 0.5) of the clamped alpha, NaN to 0.
  CHECK(alphaLevel(0.0f) == 0);
  CHECK(alphaLevel(1.0f) == 255);
  CHECK(alphaLevel(0.5f) == 128);
  CHECK(alphaLevel(0.4999f) == 127);
  CHECK(alphaLevel(-3.0f) == 0);
  CHECK(alphaLevel(7.0f) == 255);
  CHECK(alphaLevel(std::numeric_limits<float>::quiet_NaN()) == 0);
}

namespace {

// resolveRow at `lanes` over every pixel of `in`, then over short runs at
// every offset (the sixteen-lane path's last, partial group), with bytes
// past a run left alone; the number of pixels whose bytes differ from the
// one-pixel rule's.
long resolveMismatches(const std::vector<glm::vec4>& in, Blending holding, int samples, int lanes) {
  std::vector<Rgba8> plain(in.size()), wide(in.size());
  resolveRow(in.data(), plain.data(), in.size(), holding, samples, 1);
  resolveRow(in.data(), wide.data(), in.size(), holding, samples, lanes);
  long differing = 0;
  for (std::size_t i = 0; i < in.size(); ++i) differing += plain[i] == wide[i] ? 0 : 1;
  for (std::size_t n = 0; n <= 9; ++n)
    for (std::size_t at = 0; at + n + 1 <= std::min<std::size_t>(in.size(), 40); ++at) {
      std::vector<Rgba8> run(n + 1, Rgba8{1, 2, 3, 4});
      resolveRow(&in[at], run.data(), n, holding, samples, lanes);
      for (std::size_t i = 0; i < n; ++i) differing += run[i] == plain[at + i] ? 0 : 1;
      differing += run[n] == Rgba8{1, 2, 3, 4} ? 0 : 1;
    }
  return differing;
}

}  // namespace

TEST_CASE("Resolve: sixteen lanes give the one-pixel rule's bytes near every threshold, across [0, 1], out of range, both holdings, 1 to 4096 samples") {
  if (lanesHere({16}).empty()) return;
  const SrgbTables& t = srgbTables();
  std::vector<float> channels;
  for (int k = 1; k < 256; ++k)  // 40 floats either side of every threshold
    for (int d = -40; d <= 40; ++d) channels.push_back(std::bit_cast<float>(std::bit_cast<std::uint32_t>(t.thresholds[static_cast<std::size_t>(k)]) + static_cast<std::uint32_t>(d)));
  for (std::uint32_t bits = 0; bits <= std::bit_cast<std::uint32_t>(1.0f); bits += 9973) channels.push_back(std::bit_cast<float>(bits));  // [0, 1]
  const float specials[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                            -0.0f, 0.0f, 1.0f, 1.0000001f, -1e-30f, 1e-40f, 0.0031308f, 3.0f, 1e30f};
  channels.insert(channels.end(), std::begin(specials), std::end(specials));
  std::mt19937 random(2048);
  std::shuffle(channels.begin(), channels.end(), random);
  std::uniform_real_distribution<float> alpha(-0.25f, 1.25f);
  std::vector<glm::vec4> pixels;
  for (std::size_t i = 0; i + 3 <= channels.size(); i += 3) {
    const std::size_t p = i / 3;  // every seventh pixel's alpha special (0 and -0 among them), the rest in and out of [0, 1]
    const float a = p % 7 == 0 ? specials[(p / 7) % std::size(specials)] : alpha(random);
    pixels.push_back({channels[i], channels[i + 1], channels[i + 2], a});
  }
  REQUIRE(pixels.size() > 40000);
  for (const Blending holding : {Blending::Straight, Blending::Premultiplied})
    for (const int samples : {1, 3, 4096}) {
      INFO("premultiplied " << (holding == Blending::Premultiplied) << ", samples " << samples);
      CHECK(resolveMismatches(pixels, holding, samples, 16) == 0);
    }
  // The one-pixel rule itself is held to encodePixel above; here, that the
  // exact thresholds land on their own level at sixteen lanes too.
  std::vector<glm::vec4> edges;
  for (int k = 1; k < 256; ++k) edges.push_back(glm::vec4(t.thresholds[static_cast<std::size_t>(k)], std::bit_cast<float>(std::bit_cast<std::uint32_t>(t.thresholds[static_cast<std::size_t>(k)]) - 1u), 0.0f, 1.0f));
  std::vector<Rgba8> levels(edges.size());
  resolveRow(edges.data(), levels.data(), edges.size(), Blending::Straight, 1, 16);
  int wrong = 0;
  for (int k = 1; k < 256; ++k) wrong += levels[static_cast<std::size_t>(k - 1)].r == k && levels[static_cast<std::size_t>(k - 1)].g == k - 1 ? 0 : 1;
  CHECK(wrong == 0);
}

#if !defined(__SANITIZE_ADDRESS__)
TEST_CASE("Resolve: sixteen lanes give every float of [0, 1] the level its thresholds give") {
  if (lanesHere({16}).empty()) return;
  const SrgbTables& t = srgbTables();
  constexpr std::size_t kChunk = 1 << 14;
  std::vector<glm::vec4> in(kChunk);
  std::vector<Rgba8> out(kChunk);
  long wrong = 0;
  const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
  for (std::uint32_t first = 0; first <= one; first += kChunk) {
    const std::size_t n = std::min<std::size_t>(kChunk, one - first + 1);
    for (std::size_t i = 0; i < n; ++i) {
      const float c = std::bit_cast<float>(first + static_cast<std::uint32_t>(i));
      in[i] = glm::vec4(c, c, c, 1.0f);
    }
    resolveRow(in.data(), out.data(), n, Blending::Straight, 1, 16);
    for (std::size_t i = 0; i < n; ++i) {
      const float c = in[i].r;
      const unsigned level = out[i].r;
      wrong += t.thresholds[level] <= c && c < t.thresholds[level + 1] && out[i].g == level && out[i].b == level ? 0 : 1;
    }
  }
  CHECK(wrong == 0);
}
#endif

TEST_CASE("CPU renderer: the image does not depend on the thread count, nor on the frames rendered before") {
  const Scene scene = makeDefaultScene();
  for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
    RenderSettings s;
    s.width = 301;  // not a multiple of the 64-pixel tiles
    s.height = 157;
    s.shading = mode;
    s.shadows.mapSize = 300;
    s.cullBackFaces = mode != ShadingMode::Gouraud;
    CAPTURE(static_cast<int>(mode));
    const Image one = render(*makeCpuRenderer(1), scene, s);
    for (int threads : {2, 3, 7}) {
      CAPTURE(threads);
      CHECK(render(*makeCpuRenderer(threads), scene, s) == one);
    }
    // A renderer that drew another view first (other shadow-map tiles) draws the same frame.
    auto reused = makeCpuRenderer(2);
    RenderSettings other = s;
    other.camera.source = Source::Manual;
    other.camera.eye = {-4.0f, 6.0f, -3.0f};
    other.lightSource = Source::Manual;
    Light moved = scene.lights.front();
    moved.position = {3.0f, 5.0f, -2.0f};
    other.lights = {moved};
    (void)render(*reused, scene, other);
    CHECK(render(*reused, scene, s) == one);
    CHECK(render(*reused, scene, s) == one);
  }
}

TEST_CASE("Phong batch: four, eight and sixteen lanes at a time, and twice eight or sixteen, give the bits of illuminate<float>, shade and the sRGB encode, per pixel") {
  INFO("this CPU runs " << widestLanes() << " lanes");
  for (int lanes : lanesHere({1, 4, 8, 16})) {
    const Scene scene = makeDefaultScene();
    std::mt19937 random(12345);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), coordinate(-3.0f, 3.0f);
    // PCF radius 0, 1 (one four-texel load a row) and 2 (two): the shadow lookups' row loads and their per-texel fallback.
    for (int pcfRadius : {1, 0, 2})
    for (SpecularModel model : {SpecularModel::BlinnPhong, SpecularModel::Phong})
      for (bool perspective : {true, false}) {
        if (pcfRadius != 1 && (model != SpecularModel::BlinnPhong || !perspective)) continue;
        RenderSettings s;
        s.shadows.pcfRadius = pcfRadius;
        s.specular = model;
        s.camera.projection = perspective ? ProjectionKind::Perspective : ProjectionKind::Parallel;
        s.shadows.mapSize = 64;
        s.lightSource = Source::Manual;
        s.lights.clear();
        for (LightKind kind : {LightKind::Point, LightKind::Spot, LightKind::Directional, LightKind::Point}) {
          Light light;
          light.kind = kind;
          light.position = {coordinate(random), 4.0f + unit(random), coordinate(random)};
          light.direction = glm::normalize(glm::vec3(coordinate(random), -4.0f, coordinate(random)));
          light.attenuation = {1.0f, 0.1f * unit(random), 0.02f * unit(random)};
          light.spotCutoffDeg = 35.0f;
          light.castsShadow = s.lights.size() != 3;  // the last light has no map
          s.lights.push_back(light);
        }
        const FrameInputs frame = buildFrameInputs(scene, s);
        REQUIRE(frame.shadowLayerCount > 0);
        ShadowMaps maps;
        maps.reset(frame.shadows.mapSize, frame.shadowLayerCount);
        for (float& d : maps.depth) d = unit(random);  // some texels nearer than the points, some farther

        // Four runs of pixels, each shaded to its end (a flush, as at the end of a tile), so that every width
        // meets a short last batch: 21, 13, 6 and 3 pixels of a batch of 32 (twice sixteen lanes); 5, 13, 6
        // and 3 of 16 (twice eight); 1, 1, 2 and 3 of four.
        constexpr int kRuns[] = {1013, 1005, 1958, 1955};
        constexpr int kPixels = 1013 + 1005 + 1958 + 1955;
        ColorBuffer batched(kPixels, 1, glm::vec4(0.0f)), scalar(kPixels, 1, glm::vec4(0.0f));
        std::deque<CourseMaterial> materials;  // each pixel its own material
        cpu::PhongBatch batch(frame, maps, batched.data(), lanes);
        glm::vec3 anchor(0.0f);
        for (int run = 0, i = 0; run < 4; ++run) {
          for (int j = 0; j < kRuns[run]; ++j, ++i) {
            // Of every four runs of 16 pixels, the first scatters (over several faces of a point light's cube);
            // the others lie close together, as a surface's pixels do, so that the lanes of a batch read one face
            // (one projection for all of them): the second alone, the third and fourth (32 pixels) as one.
            const int group = (j / 16) % 4;
            if (j % 16 == 0 && group != 3) anchor = {coordinate(random), coordinate(random) * 0.3f, coordinate(random)};
            const glm::vec3 P = group == 0 ? glm::vec3{coordinate(random), coordinate(random) * 0.3f, coordinate(random)}
                                           : anchor + 0.02f * glm::vec3{coordinate(random), coordinate(random), coordinate(random)};
            const glm::vec3 N = glm::normalize(glm::vec3(coordinate(random), coordinate(random), coordinate(random)));
            const glm::vec3 baseColor{unit(random), unit(random), unit(random)};
            CourseMaterial material;
            material.emissive = glm::vec3(0.05f * unit(random));
            material.ka = unit(random), material.kd = unit(random), material.ks = unit(random);
            material.shininess = 1.0f + 200.0f * unit(random);
            const bool back = i % 5 == 0;
            const glm::vec3 interpolated = N * (0.5f + unit(random));  // not unit length, as interpolated normals are
            materials.push_back(material);
            batch.add(static_cast<std::size_t>(i), P, interpolated, back, baseColor, materials.back(), materials.back().emissive, 0.0f);
            const glm::vec3 lit = back ? -normalize3(interpolated) : normalize3(interpolated);
            scalar.at(i, 0) =
                glm::vec4(shade(illuminate(frame, maps, laneMaterial(material), P, lit, viewVector<float>(frame, P)), baseColor), 1.0f);
          }
          batch.flush();
        }
        CAPTURE(static_cast<int>(model));
        CAPTURE(perspective);
        CAPTURE(pcfRadius);
        CAPTURE(lanes);
        int differing = 0;
        for (int i = 0; i < kPixels; ++i) differing += std::memcmp(&batched.at(i, 0), &scalar.at(i, 0), sizeof(glm::vec4)) == 0 ? 0 : 1;  // to the bit
        CHECK(differing == 0);
        // The comparison means something: lit, shadowed and unlit pixels all occur.
        std::set<int> levels;
        for (int i = 0; i < kPixels; ++i) levels.insert(encodeLevel(scalar.at(i, 0).r));
        CHECK(levels.size() > 100);
      }
  }
}

TEST_CASE("Phong batch: blended at every width, pixels scattered, gives blend's bits over what each pixel holds, both equations, additive or not") {
  const Scene scene = makeDefaultScene();
  const FrameInputs frame = buildFrameInputs(scene, RenderSettings{});
  ShadowMaps maps;
  maps.reset(frame.shadows.mapSize, frame.shadowLayerCount);
  std::fill(maps.depth.begin(), maps.depth.end(), 1.0f);
  const std::vector<int> widths = lanesHere({1, 4, 8, 16});
  std::mt19937 random(4242);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), coordinate(-3.0f, 3.0f), outOfRange(-0.5f, 1.5f);
  // Runs flushed at 37, 50 and 13 pixels, so that each width meets full and short batches; the pixels
  // scattered over the buffer, so that loads and stores gather rather than walk a row.
  constexpr int kRuns[] = {37, 50, 13}, kPixels = 100;
  for (const int lanes : widths)
    for (const Blending blending : {Blending::Straight, Blending::Premultiplied})
      for (const bool additive : {false, true}) {
        CAPTURE(lanes);
        CAPTURE(static_cast<int>(blending));
        CAPTURE(additive);
        ColorBuffer batched(kPixels, 1, glm::vec4(0.0f)), plain(kPixels, 1, glm::vec4(0.0f));
        for (int i = 0; i < kPixels; ++i) {
          batched.at(i, 0) = {unit(random), unit(random), unit(random), i % 9 == 0 ? 0.0f : unit(random)};  // some pixels hold nothing
          plain.at(i, 0) = batched.at(i, 0);
        }
        std::vector<std::size_t> offsets(kPixels);
        for (int i = 0; i < kPixels; ++i) offsets[static_cast<std::size_t>(i)] = static_cast<std::size_t>(i);
        std::shuffle(offsets.begin(), offsets.end(), random);
        const BlendOver over{blending, additive};
        cpu::PhongBatch batch(frame, maps, batched.data(), lanes, &over);
        std::deque<CourseMaterial> materials;
        for (int run = 0, i = 0; run < 3; ++run) {
          for (int j = 0; j < kRuns[run]; ++j, ++i) {
            const glm::vec3 P{coordinate(random), 0.3f * coordinate(random), coordinate(random)};
            const glm::vec3 N = glm::normalize(glm::vec3(coordinate(random), coordinate(random), coordinate(random)));
            const glm::vec3 baseColor{unit(random), unit(random), unit(random)};
            CourseMaterial material;
            material.ka = unit(random), material.kd = unit(random), material.ks = unit(random), material.shininess = 1.0f + 100.0f * unit(random);
            materials.push_back(material);
            float alpha = outOfRange(random);  // clamped to [0, 1] by the blend, NaN to 0
            if (i % 11 == 0) alpha = std::numeric_limits<float>::quiet_NaN();
            const std::size_t at = offsets[static_cast<std::size_t>(i)];
            const bool back = i % 4 == 0;
            batch.add(at, P, N, back, baseColor, materials.back(), material.emissive, 0.0f, alpha);
            const glm::vec3 lit = back ? -normalize3(N) : normalize3(N);
            const glm::vec3 C = shade(illuminate(frame, maps, laneMaterial(material), P, lit, viewVector<float>(frame, P)), baseColor);
            plain.at(static_cast<int>(at), 0) = blend(plain.at(static_cast<int>(at), 0), C, alpha, blending, additive);
          }
          batch.flush();
        }
        int differing = 0;
        for (int i = 0; i < kPixels; ++i) differing += std::memcmp(&batched.at(i, 0), &plain.at(i, 0), sizeof(glm::vec4)) == 0 ? 0 : 1;  // to the bit
        CHECK(differing == 0);
        std::set<int> levels;  // the comparison means something: the blends differ from pixel to pixel
        for (int i = 0; i < kPixels; ++i) levels.insert(encodeLevel(plain.at(i, 0).r));
        CHECK(levels.size() > 30);
      }
}

TEST_CASE("Phong batch: a run of a triangle's pixels queued at once gives the bits of each pixel interpolated and queued alone") {
  const Scene scene = makeDefaultScene();
  RenderSettings s;
  const FrameInputs frame = buildFrameInputs(scene, s);
  ShadowMaps maps;
  maps.reset(frame.shadows.mapSize, frame.shadowLayerCount);
  std::fill(maps.depth.begin(), maps.depth.end(), 1.0f);
  std::mt19937 random(777);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), varying(-2.0f, 2.0f);
  // A triangle over a 160 x 8 block of pixels, its six varyings (P, N) and 1/w at each corner.
  float corner[3][6];
  for (auto& c : corner)
    for (float& v : c) v = varying(random);
  const cpu::InterpolationVertex a{3.25f, 1.5f, 0.5f, 0.9f, corner[0]}, b{300.5f, 2.75f, 0.4f, 0.35f, corner[1]}, c{5.5f, 97.25f, 0.6f, 0.6f, corner[2]};
  cpu::Interpolation in(a, b, c);
  in.setUpVaryings(6);
  CourseMaterial material;
  material.ka = 0.2f, material.kd = 0.7f, material.ks = 0.5f, material.shininess = 37.0f, material.emissive = {0.01f, 0.02f, 0.03f};
  const glm::vec3 baseColor{0.8f, 0.4f, 0.2f};
  constexpr int kWidth = 160, kRows = 8;  // a row holds runs of 1 to 16 (136 pixels)
  for (const int lanes : lanesHere({1, 4, 8, 16})) {
    for (const bool blended : {false, true}) {
      CAPTURE(lanes);
      CAPTURE(blended);
      const BlendOver over{Blending::Straight, false};
      // α for every pixel, and room for a run's read of sixteen past the last (as the tile's arrays have).
      std::vector<float> alpha(kWidth * kRows + 16);
      for (float& x : alpha) x = unit(random);
      ColorBuffer wide(kWidth, kRows, glm::vec4(0.25f, 0.5f, 0.75f, 0.5f)), alone(kWidth, kRows, glm::vec4(0.25f, 0.5f, 0.75f, 0.5f));
      cpu::PhongBatch run(frame, maps, wide.data(), lanes, blended ? &over : nullptr), one(frame, maps, alone.data(), lanes, blended ? &over : nullptr);
      // Runs of every length from 1 to the batch's lanes, in turn, so that they start at every lane of
      // the queue and some straddle the point where the batch is shaded.
      int length = 0, runs = 0;
      std::set<int> lengths;
      for (int py = 0; py < kRows; ++py)
        for (int px = 0; px < kWidth;) {
          const int n = std::min(length % lanes + 1, kWidth - px);
          ++length, ++runs;
          lengths.insert(n);
          const auto at = static_cast<std::size_t>(py * kWidth + px);
          const bool back = (runs + py) % 3 == 0;
          run.addRun(n, at, in, 40 + px, 20 + py, back, baseColor, material, blended ? &alpha[at] : nullptr);
          for (int k = 0; k < n; ++k) {
            const float w = in.inverseWAt(40 + px + k, 20 + py);
            one.add(at + static_cast<std::size_t>(k), in.varying3At(0, 40 + px + k, 20 + py, w), in.varying3At(3, 40 + px + k, 20 + py, w), back,
                    baseColor, material, material.emissive, 0.0f, blended ? alpha[at + static_cast<std::size_t>(k)] : 1.0f);
          }
          px += n;
        }
      run.flush(), one.flush();
      CHECK(static_cast<int>(lengths.size()) == lanes);  // every length was queued
      int differing = 0;
      for (int i = 0; i < kWidth * kRows; ++i) differing += std::memcmp(&wide.data()[i], &alone.data()[i], sizeof(glm::vec4)) == 0 ? 0 : 1;  // to the bit
      CHECK(differing == 0);
      // The comparison means something: the pixels are lit differently across the block, and none kept the clear colour.
      std::set<int> levels;
      int cleared = 0;
      for (int i = 0; i < kWidth * kRows; ++i) {
        levels.insert(encodeLevel(alone.data()[i].r));
        cleared += wide.data()[i] == glm::vec4(0.25f, 0.5f, 0.75f, 0.5f) ? 1 : 0;
      }
      CHECK(levels.size() > 20);
      CHECK(cleared == 0);
    }
  }
}

#if defined(__SSE2__)
TEST_CASE("Cube faces: cubeFaceLanes picks cubeFace's face in each lane, ties, signed zeros, infinities and NaN included") {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const float special[] = {0.0f, -0.0f, 1.0f, -1.0f, 2.0f, -2.0f, inf, -inf, nan};
  std::vector<glm::vec3> vectors;
  for (float x : special)
    for (float y : special)
      for (float z : special) vectors.push_back({x, y, z});  // every tie of |x|, |y| and |z|
  std::mt19937 random(5);
  std::uniform_real_distribution<float> any(-10.0f, 10.0f);
  for (int i = 0; i < 4000; ++i) vectors.push_back({any(random), any(random), any(random)});
  while (vectors.size() % 4 != 0) vectors.push_back({1.0f, 0.0f, 0.0f});
  std::set<int> faces;
  int differing = 0;
  for (std::size_t i = 0; i < vectors.size(); i += 4) {
    alignas(16) float c[3][4];
    for (int k = 0; k < 4; ++k)
      for (int a = 0; a < 3; ++a) c[a][k] = vectors[i + static_cast<std::size_t>(k)][a];
    const Vec3x4 d(Float4(_mm_load_ps(c[0])), Float4(_mm_load_ps(c[1])), Float4(_mm_load_ps(c[2])));
    alignas(16) std::int32_t lanes[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes), cubeFaceLanes<Float4>(d).v);
    for (int k = 0; k < 4; ++k) {
      const int face = cubeFace(vectors[i + static_cast<std::size_t>(k)]);
      faces.insert(face);
      differing += lanes[k] == face ? 0 : 1;
    }
  }
  CHECK(differing == 0);
  CHECK(faces.size() == 6);
}
#endif

TEST_CASE("Phong batch: a width this CPU or build does not run is refused") {
  const Scene scene = makeDefaultScene();
  const FrameInputs frame = buildFrameInputs(scene, RenderSettings{});
  ShadowMaps maps;
  ColorBuffer pixels(4, 1, glm::vec4(0.0f));
  CHECK_THROWS_AS(cpu::PhongBatch(frame, maps, pixels.data(), 2), Error);
  CHECK_THROWS_AS(cpu::PhongBatch(frame, maps, pixels.data(), 32), Error);
  if (widestLanes() < 8) CHECK_THROWS_AS(cpu::PhongBatch(frame, maps, pixels.data(), 8), Error);
  if (widestLanes() < 16) CHECK_THROWS_AS(cpu::PhongBatch(frame, maps, pixels.data(), 16), Error);
}

TEST_CASE("Depth rows: lessRow's four- and sixteen-lane tests write the depths and ids the one-pixel test writes") {
  for (const int lanes : lanesHere({4, 16})) {
    CAPTURE(lanes);
    std::mt19937 random(31);
    std::uniform_real_distribution<float> unit(-0.2f, 1.2f), slope(-0.01f, 0.01f);
    for (int trial = 0; trial < 500; ++trial) {
      const cpu::Plane z{unit(random), slope(random), slope(random)};
      const int x0 = trial % 13, x1 = x0 + trial % 29, py = trial % 7;
      float fast[64], plain[64];
      std::uint32_t fastIds[64], plainIds[64];
      for (int i = 0; i < 64; ++i) fast[i] = plain[i] = unit(random), fastIds[i] = plainIds[i] = 7;
      if (trial % 11 == 0) fast[3] = plain[3] = std::numeric_limits<float>::quiet_NaN();  // a NaN depth keeps nothing out: !(z < NaN)
      for (int px = x0; px <= x1; px += 3) fast[px - x0] = plain[px - x0] = cpu::depthAt(z, px, py);  // equal depths: LESS keeps the first
      cpu::lessRowOnLanes(lanes, z, x0, x1, py, fast, fastIds, 9);
      for (int px = x0; px <= x1; ++px) {
        const float d = cpu::depthAt(z, px, py);
        if (d < plain[px - x0]) plain[px - x0] = d, plainIds[px - x0] = 9;
      }
      CHECK(std::memcmp(fast, plain, sizeof fast) == 0);  // and nothing past x1 written
      CHECK(std::memcmp(fastIds, plainIds, sizeof fastIds) == 0);
    }
  }
}

TEST_CASE("Depth rows: lessCovered writes the depths and ids the one-pixel test writes at the covered pixels of a block's row, and nothing else") {
  std::mt19937 random(41);
  std::uniform_real_distribution<float> unit(-0.2f, 1.2f), slope(-0.01f, 0.01f);
  int written = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const cpu::Plane z{unit(random), slope(random), slope(random)};
    const int bx = 8 * (trial % 9), py = trial % 7;
    const auto covered = static_cast<unsigned>(random() % 255u);  // 0 to 254: some pixels of the eight, none or not all
    float fast[8], plain[8];
    std::uint32_t fastIds[8], plainIds[8];
    for (int i = 0; i < 8; ++i) fast[i] = plain[i] = unit(random), fastIds[i] = plainIds[i] = 7;
    if (trial % 11 == 0) fast[3] = plain[3] = std::numeric_limits<float>::quiet_NaN();  // a NaN depth keeps nothing out: !(z < NaN)
    if (trial % 5 == 0) fast[trial % 8] = plain[trial % 8] = cpu::depthAt(z, bx + trial % 8, py);  // equal depths: LESS keeps the first
    cpu::lessCovered(z, bx, covered, py, fast, trial % 3 == 0 ? nullptr : fastIds, 9);
    for (int k = 0; k < 8; ++k) {
      if (!(covered & (1u << k))) continue;
      const float d = cpu::depthAt(z, bx + k, py);
      if (d < plain[k]) plain[k] = d, plainIds[k] = trial % 3 == 0 ? 7 : 9, ++written;
    }
    CHECK(std::memcmp(fast, plain, sizeof fast) == 0);
    CHECK(std::memcmp(fastIds, plainIds, sizeof fastIds) == 0);
  }
  CHECK(written > 500);  // the test wrote depths, not only kept them
}

TEST_CASE("Depth rows: frontRow's four- and sixteen-lane tests take the pixels the one-pixel test takes, and report the first and last") {
  for (const int lanes : lanesHere({4, 16})) {
    CAPTURE(lanes);
    std::mt19937 random(37);
    std::uniform_real_distribution<float> unit(-0.2f, 1.2f), slope(-0.01f, 0.01f);
    int none = 0, some = 0;
    for (int trial = 0; trial < 500; ++trial) {
      const cpu::Plane z{unit(random), slope(random), slope(random)};
      const int x0 = trial % 13, x1 = x0 + trial % 29, py = trial % 7;
      float depth[64], before[64];
      std::uint32_t fastIds[64], plainIds[64];
      for (int i = 0; i < 64; ++i) depth[i] = unit(random), fastIds[i] = plainIds[i] = 7;
      if (trial % 11 == 0) depth[3] = std::numeric_limits<float>::quiet_NaN();  // a NaN depth keeps nothing out: !(z < NaN)
      for (int px = x0; px <= x1; px += 3) depth[px - x0] = cpu::depthAt(z, px, py);  // equal depths: LESS does not take them
      std::memcpy(before, depth, sizeof depth);
      const cpu::TakenRun taken = cpu::frontRowOnLanes(lanes, z, x0, x1, py, depth, fastIds, 9);
      int first = x1 + 1, last = x0 - 1;
      for (int px = x0; px <= x1; ++px)
        if (cpu::depthAt(z, px, py) < depth[px - x0]) plainIds[px - x0] = 9, first = std::min(first, px), last = px;
      CHECK(std::memcmp(fastIds, plainIds, sizeof fastIds) == 0);  // and nothing past x1 written
      CHECK(std::memcmp(depth, before, sizeof depth) == 0);  // read, not written
      CHECK(taken.first == first);
      CHECK(taken.last == last);
      (first > last ? none : some) += 1;
    }
    CHECK(none > 10);  // rows with nothing taken and rows with pixels taken both occur
    CHECK(some > 100);
  }
}

#if defined(__SSE2__)
TEST_CASE("Blending: blendPixels' four lanes give blend's bits per pixel at their offsets, both equations, additive or not, alpha out of range or NaN") {
  std::mt19937 random(47);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), wide(-0.5f, 1.5f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const Blending blending : {Blending::Straight, Blending::Premultiplied})
    for (const bool additive : {false, true})
      for (int trial = 0; trial < 200; ++trial) {
        float held[32], fragments[12], alpha[4];  // eight RGBA pixels, four of which the lanes blend over
        for (float& c : held) c = unit(random);
        for (float& c : fragments) c = wide(random);
        for (float& a : alpha) a = wide(random);
        std::size_t offsets[8] = {0, 1, 2, 3, 4, 5, 6, 7};
        std::shuffle(std::begin(offsets), std::end(offsets), random);
        const int count = 1 + trial % 4;  // the lanes past count touch nothing
        if (trial % 5 == 0) alpha[trial % 4] = nan;
        if (trial % 7 == 0) held[3 + 4 * offsets[trial % 4]] = 0.0f, alpha[trial % 4] = 0.0f;  // nothing behind, nothing in front: α_o = 0
        if (trial % 3 == 0) held[3 + 4 * offsets[(trial + 1) % 4]] = 1.0f;
        float plain[32];
        std::memcpy(plain, held, sizeof plain);
        for (int k = 0; k < count; ++k) {
          const float* behind = held + 4 * offsets[k];
          const glm::vec4 out = blend({behind[0], behind[1], behind[2], behind[3]}, {fragments[k], fragments[4 + k], fragments[8 + k]}, alpha[k],
                                           blending, additive);
          std::memcpy(plain + 4 * offsets[k], &out, sizeof out);
        }
        const Vec3x4 color(Float4(_mm_loadu_ps(fragments)), Float4(_mm_loadu_ps(fragments + 4)), Float4(_mm_loadu_ps(fragments + 8)));
        blendPixels(held, offsets, count, color, Float4(_mm_loadu_ps(alpha)), BlendOver{blending, additive});
        CAPTURE(count);
        CHECK(std::memcmp(held, plain, sizeof plain) == 0);
      }
}
#endif
