#include "cpu/cpu_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "common/quote.h"
#include "common/stopwatch.h"
#include "shading/environment.h"
#include "cpu/frame_buffers.h"
#include "shading/lighting.h"
#include "cpu/passes.h"
#include "common/lane_width.h"
#include "cpu/area_averaged_frame.h"
#include "shading/resolve.h"
#include "cpu/volume_pass.h"
#include "pipeline/antialiasing.h"
#include "cpu/scanline_zbuffer.h"
#include "common/thread_pool.h"
#include "pipeline/frame_checks.h"
#include "pipeline/shadow_pass_key.h"
#include "pipeline/stage_frames.h"

namespace facet {
namespace {

// One frame: world positions once, then pass 1 per shadow-map face and pass 2,
// each in the phases of cpu/frame_buffers.h on a pool of threads that lives
// as long as the renderer, with buffers (vertices, bins, shadow maps) kept
// from frame to frame.
class CpuRenderer final : public Renderer {
 public:
  CpuRenderer(int threads, int lanes)
      : pool_(threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()))) {
    buffers_.lanes = lanes > 0 ? lanes : widestLanes();
    checkLanes(buffers_.lanes);
  }

  std::string description() const override {
    return "cpu rasterizer, " + countOf(pool_.size(), "thread") + ", " + std::to_string(buffers_.lanes) + " lanes";
  }

  // Each output asked from passes of its own, in FrameOutput order.
  RenderResult render(const Scene& scene, const FrameInputs& frame, const FrameOutputs& asked) override {
    RenderResult result = asked.has(FrameOutput::Image) ? drawImage(scene, frame) : RenderResult{};
    if (asked.has(FrameOutput::TriangleIds)) result.triangleIds = visibleTriangles(scene, frame);
    if (asked.has(FrameOutput::FragmentCounts)) result.fragmentCounts = fragmentCounts(scene, frame);
    if (asked.has(FrameOutput::Depth)) result.depth = depthBuffer(scene, frame);
    if (asked.has(FrameOutput::ShadowMaps)) result.shadowMaps = shadowMaps(scene, frame);
    if (asked.has(FrameOutput::Normals)) result.normals = normals(scene, frame);
    return result;
  }

  void forgetShadowMaps() override { mapsDrawn_ = {}; }

 private:
  RenderResult drawImage(const Scene& scene, const FrameInputs& frame) {
    check_(scene, frame);
    RenderResult result;
    cpu::prepareFrame(pool_, buffers_, scene, frame);
    shadowPasses(scene, frame, result);
    if (frame.areaAveraged) {  // the course's exact area-weighted averaging, lit by these maps, in place of the tiles
      RenderResult area = cpu::renderAreaAveraged(scene, frame, maps_);
      area.timings.insert(area.timings.begin(), result.timings.begin(), result.timings.end());
      return area;
    }

    const auto start = std::chrono::steady_clock::now();
    RayCastCounts volumeCounts;
    // One pass into the colour buffer: the lit pass sets each tile to the background (one colour, or the
    // map behind everything in each pixel's view direction) before drawing into it. A single-sample
    // frame with no volume cast after it is resolved by the lit pass tile by tile, into `image`.
    const auto drawPass = [&](const FrameInputs& pass, Image* image) {
      if (!image) color_.resize(pass.width, pass.height);
      cpu::litPass(pool_, buffers_, scene, pass, maps_, color_, {.background = true, .image = image});
      if (pass.volume.placed) volumeCounts += cpu::volumePass(pool_, pass, buffers_.depth, color_);
    };
    const bool resolvedByTile = frame.samples.empty() && !frame.volume.placed;
    if (resolvedByTile) {
      result.image = recycledImage();
      result.image.resize(frame.width, frame.height);  // every tile resolves into it
      drawPass(frame, &result.image);
      result.timings.push_back({"lit pass and resolve", millisecondsSince(start)});
    } else if (frame.samples.empty()) {
      drawPass(frame, nullptr);
      result.timings.push_back({"lit pass", millisecondsSince(start)});
    } else {  // anti-aliasing: a pass per sample, summed premultiplied (PIPELINE.md, "Shading")
      for (std::size_t i = 0; i < frame.samples.size(); ++i) {
        drawPass(sampleFrame(frame, frame.samples[i]), nullptr);
        accumulate(pool_, color_, frame.blending, sum_, i == 0);
      }
      result.timings.push_back({"lit pass (" + std::to_string(frame.samples.size()) + " samples)", millisecondsSince(start)});
    }
    if (frame.volume.placed) {
      const auto share = [&](std::uint64_t n) {
        const double all = static_cast<double>(volumeCounts.samples + volumeCounts.skippedEmpty + volumeCounts.savedByTermination);
        return all > 0 ? 100.0 * static_cast<double>(n) / all : 0.0;
      };
      char line[256];
      std::snprintf(line, sizeof line, "volume ray casting: %llu samples taken; empty-space skipping saved %llu (%.1f%%), early termination %llu (%.1f%%)",
                    static_cast<unsigned long long>(volumeCounts.samples), static_cast<unsigned long long>(volumeCounts.skippedEmpty),
                    share(volumeCounts.skippedEmpty), static_cast<unsigned long long>(volumeCounts.savedByTermination),
                    share(volumeCounts.savedByTermination));
      result.notes.push_back(line);
    }
    if (!resolvedByTile) {
      result.image = recycledImage();
      const auto resolveStart = std::chrono::steady_clock::now();
      if (frame.samples.empty()) resolve(pool_, color_, frame.blending, 1, buffers_.lanes, result.image);
      else resolve(pool_, sum_, Blending::Premultiplied, static_cast<int>(frame.samples.size()), buffers_.lanes, result.image);
      result.timings.push_back({"resolve", millisecondsSince(resolveStart)});
    }
    if (frame.hsr == HiddenSurface::Scanline) {
      const auto frameDepth = static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height) * sizeof(float);
      result.notes.push_back("scanline z-buffer: " + countOf(static_cast<std::size_t>(pool_.size()), "row") + " of depth, " +
                             countOf(cpu::scanlineDepthBytes(frame.width, pool_.size()), "byte") + "; a z-buffer of the frame: " +
                             countOf(frameDepth, "byte"));
    }
    return result;
  }

  std::vector<std::uint32_t> visibleTriangles(const Scene& scene, const FrameInputs& frame) {
    return perPixel(scene, frame, [&](std::vector<std::uint32_t>& ids, ColorBuffer& unused) {
      cpu::litPass(pool_, buffers_, scene, frame, maps_, unused, {.triangleIds = &ids});
    });
  }

  std::vector<std::uint32_t> fragmentCounts(const Scene& scene, const FrameInputs& frame) {
    return perPixel(scene, frame, [&](std::vector<std::uint32_t>& counts, ColorBuffer& unused) {
      cpu::litPass(pool_, buffers_, scene, frame, maps_, unused, {.fragmentCounts = &counts});
    });
  }

  // The lit pass of the frame at the pixel centres (one pass, whatever its samples), keeping its z-buffer.
  std::vector<float> depthBuffer(const Scene& scene, const FrameInputs& frame) {
    check_(scene, frame);
    cpu::prepareFrame(pool_, buffers_, scene, frame);
    RenderResult maps;
    shadowPasses(scene, frame, maps);
    color_.reset(frame.width, frame.height, glm::vec4(0.0f));
    cpu::litPass(pool_, buffers_, scene, frame, maps_, color_, {.keepDepth = true});
    return buffers_.depth;
  }

  ShadowMapTexels shadowMaps(const Scene& scene, const FrameInputs& frame) {
    check_(scene, frame);
    if (frame.shadowLayerCount == 0) return {};
    cpu::prepareFrame(pool_, buffers_, scene, frame);
    RenderResult unused;
    shadowPasses(scene, frame, unused);  // or the maps kept from an earlier frame with the same pass 1
    return {maps_.size, maps_.layers, {maps_.depth.begin(), maps_.depth.end()}};
  }

  std::vector<glm::vec4> normals(const Scene& scene, const FrameInputs& frame) {
    const FrameInputs drawn = normalsFrame(frame);
    check_(scene, drawn);
    cpu::prepareFrame(pool_, buffers_, scene, drawn);  // no shadow pass: the frame has no lights
    color_.reset(drawn.width, drawn.height, glm::vec4(0.0f));
    cpu::litPass(pool_, buffers_, scene, drawn, maps_, color_, {.normals = true});
    return {color_.data(), color_.data() + static_cast<std::size_t>(drawn.width) * static_cast<std::size_t>(drawn.height)};
  }

  // A lit pass that writes one value per pixel instead of the image: `pass(values, unusedColorBuffer)`
  // after the vertex positions and the shadow maps (the vertex stage of Gouraud reads them).
  template <class Pass>
  std::vector<std::uint32_t> perPixel(const Scene& scene, const FrameInputs& frame, Pass&& pass) {
    check_(scene, frame);
    cpu::prepareFrame(pool_, buffers_, scene, frame);
    RenderResult maps;
    shadowPasses(scene, frame, maps);
    std::vector<std::uint32_t> values(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 0u);
    ColorBuffer unused;
    pass(values, unused);
    return values;
  }

  // Pass 1 for every shadowed light's faces, unless the maps hold this frame's already (pipeline/shadow_pass_key.h).
  void shadowPasses(const Scene& scene, const FrameInputs& frame, RenderResult& result) {
    if (frame.shadowLayerCount > 0) {
      if (mapsDrawn_.matches(scene, frame)) {
        result.timings.push_back({shadowPassName(frame, true), 0.0});
        return;
      }
      mapsDrawn_ = {};  // until every face is drawn
      const auto start = std::chrono::steady_clock::now();
      maps_.reset(frame.shadows.mapSize, frame.shadowLayerCount);
      for (std::size_t l = 0; l < frame.lights.size(); ++l) {
        const FrameLight& light = frame.lights[l];
        if (!light.hasShadowMap) continue;
        for (int face = 0; face < light.frustum.faceCount; ++face) cpu::shadowPass(pool_, buffers_, scene, frame, light, face, maps_);
      }
      mapsDrawn_ = ShadowPassKey(scene, frame);
      result.timings.push_back({shadowPassName(frame, false), millisecondsSince(start)});
    }
  }

  FrameCheck check_;
  ThreadPool pool_;
  cpu::FrameBuffers buffers_;
  ShadowMaps maps_;
  ShadowPassKey mapsDrawn_;  // what maps_ holds the shadow maps of
  ColorBuffer color_;  // the lit pass's linear colours, kept from frame to frame
  ColorBuffer sum_;    // anti-aliasing: the samples' premultiplied sum
};

}  // namespace

std::unique_ptr<Renderer> makeCpuRenderer(int threads, int lanes) { return std::make_unique<CpuRenderer>(threads, lanes); }

}  // namespace facet
