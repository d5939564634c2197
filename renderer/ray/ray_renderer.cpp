#include "ray/ray_renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <utility>

#include "common/error.h"
#include "common/quote.h"
#include "common/stopwatch.h"
#include "shading/blending.h"
#include "common/lane_width.h"
#include "shading/resolve.h"
#include "common/thread_pool.h"
#include "image/color_buffer.h"
#include "pipeline/frame_checks.h"
#include "ray/ray_tracer.h"
#include "ray/traced_scene.h"
#include "scene/memory_budget.h"
#include "settings/render_settings.h"
#include "vocabulary/limits.h"

namespace facet {
namespace {

using ray::RayStatistics;
using ray::RayTracer;
using ray::TracedScene;

constexpr int kTile = 16;  // pixels a side: a worker's unit of work

class RayRenderer final : public Renderer {
 public:
  RayRenderer(int threads, RenderProgress progress)
      : pool_(threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()))), progress_(std::move(progress)) {}

  std::string description() const override { return "ray tracer, " + countOf(static_cast<std::size_t>(pool_.size()), "thread"); }

  // The image and the stages a rasterizer also reports (triangle ids, fragment counts); no z-buffer, maps or normals.
  RenderResult render(const Scene& scene, const FrameInputs& frame, const FrameOutputs& asked) override {
    refuseUndrawn(asked, {FrameOutput::Image, FrameOutput::TriangleIds, FrameOutput::FragmentCounts});
    RenderResult result = asked.has(FrameOutput::Image) ? drawImage(scene, frame) : RenderResult{};
    if (asked.has(FrameOutput::TriangleIds))
      result.triangleIds = perPixel(scene, frame, [](const RayTracer& tracer, int x, int y) { return tracer.visibleTriangle(x, y); });
    if (asked.has(FrameOutput::FragmentCounts))
      result.fragmentCounts = perPixel(scene, frame, [](const RayTracer& tracer, int x, int y) { return tracer.surfacesCrossed(x, y); });
    return result;
  }

 private:
  RenderResult drawImage(const Scene& scene, const FrameInputs& frame) {
    refuseRayImage(frame);
    RenderResult result;
    const TracedScene& traced = prepare(scene, frame, frame.ray.spheres, result);
    // Paths per pixel: ray.samples, each jittered over the pixel; with one, the antialiasing
    // offsets (the pixel's centre, or the rasterizers' grid or jittered samples). One is held
    // straight, several are summed premultiplied.
    const int paths = frame.ray.samples > 1 ? frame.ray.samples : std::max<int>(1, static_cast<int>(frame.samples.size()));
    // Motion blur: the scene placed at K times across the shutter, path k at slice k mod K.
    std::vector<RayTracer> tracers;
    if (frame.camera.shutter > 0.0f && !scene.animation.empty()) {
      // The slices' BVHs together within the frame budget: fewer of them where one is large.
      const auto fit = static_cast<int>(std::min<std::uint64_t>(kMaxShutterSlices, kFrameMemoryBudget / std::max<std::size_t>(1, traced.bytes())));
      const int slices = std::max(1, std::min(paths, fit));
      const auto buildStart = std::chrono::steady_clock::now();
      sliceFrames_.assign(static_cast<std::size_t>(slices), frame);
      slices_.clear();
      tracers.reserve(static_cast<std::size_t>(slices));
      for (int k = 0; k < slices; ++k) {
        FrameInputs& at = sliceFrames_[static_cast<std::size_t>(k)];
        placeInstances(scene, frame.time + frame.camera.shutter * (static_cast<float>(k) + 0.5f) / static_cast<float>(slices), at);
        slices_.push_back(std::make_unique<TracedScene>(scene, at, frame.ray.spheres, pool_));
        tracers.emplace_back(*slices_.back(), at);
      }
      result.timings.push_back({"BVH build (" + countOf(static_cast<std::size_t>(slices), "shutter slice") + ")", millisecondsSince(buildStart)});
      result.notes.push_back("motion blur: the scene at " + countOf(static_cast<std::size_t>(slices), "time") + " across the shutter [" +
                             std::to_string(frame.time) + ", " + std::to_string(frame.time + frame.camera.shutter) + "] s");
    } else {
      tracers.emplace_back(traced, frame);
    }
    const auto start = std::chrono::steady_clock::now();
    const bool summed = paths > 1;
    const auto seed = static_cast<std::uint32_t>(frame.ray.seed);
    color_.reset(frame.width, frame.height, glm::vec4(0.0f));
    RayStatistics statistics;
    std::mutex merging;
    forEachPixel(frame, [&](int x, int y, RayStatistics& local) {
      const auto pixel = static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(frame.width) + static_cast<std::uint32_t>(x);
      glm::vec4 sum(0.0f);
      for (int k = 0; k < paths; ++k) {
        ray::PathSampler sampler(seed, pixel, static_cast<std::uint32_t>(k));
        const glm::vec2 offset = frame.ray.samples > 1 ? ray::pixelJitter(k, paths, sampler.uniform2())
                                                       : (frame.samples.empty() ? glm::vec2(0.0f) : frame.samples[static_cast<std::size_t>(k)]);
        const glm::vec4 held = tracers[static_cast<std::size_t>(k) % tracers.size()].pixel(x, y, offset, sampler, local);
        sum = summed ? sum + premultipliedOf(held, Blending::Straight) : held;
      }
      color_.at(x, y) = sum;
    }, [&](const RayStatistics& local) {
      const std::lock_guard<std::mutex> lock(merging);
      statistics.add(local);
    });
    result.timings.push_back({"ray tracing" + (summed ? " (" + std::to_string(paths) + " paths a pixel)" : std::string()), millisecondsSince(start)});
    const auto resolveStart = std::chrono::steady_clock::now();
    result.image = recycledImage();
    resolve(pool_, color_, summed ? Blending::Premultiplied : Blending::Straight, paths, widestLanes(), result.image);
    result.timings.push_back({"resolve", millisecondsSince(resolveStart)});
    result.notes.push_back(statistics.summary());
    if (frame.hsr != HiddenSurface::ZBuffer)
      result.notes.push_back("hsr " + std::string(kHiddenSurfaceNames[static_cast<std::size_t>(frame.hsr)]) +
                             " is the rasterizers'; a ray sees the nearest surface (ray casting is its own hidden-surface removal)");
    return result;
  }

  // The frame checked, and its primitives and BVH: kept when the scene and its instances are those of the last frame.
  const TracedScene& prepare(const Scene& scene, const FrameInputs& frame, bool spheres, RenderResult& result) {
    check_(scene, frame);
    if (!traced_ || !traced_->builtFrom(scene, frame, spheres)) {
      traced_.reset();
      const auto start = std::chrono::steady_clock::now();
      traced_ = std::make_unique<TracedScene>(scene, frame, spheres, pool_);
      result.timings.push_back({"BVH build", millisecondsSince(start)});
      const ray::BvhStats& s = traced_->bvh().stats();
      result.notes.push_back("BVH: " + countOf(s.primitives, "primitive") + ", " + countOf(s.nodes, "node") + " (" + countOf(s.leaves, "leaf", "leaves") +
                             "), depth " + std::to_string(s.maxDepth) + ", " + byteCount(traced_->bytes()));
    } else {
      traced_->bind(scene, frame);
    }
    return *traced_;
  }

  // value(tracer, x, y) of every pixel, bottom row first: the stages a rasterizer also reports.
  template <class Value>
  std::vector<std::uint32_t> perPixel(const Scene& scene, const FrameInputs& frame, Value&& value) {
    RenderResult unused;
    const RayTracer tracer(prepare(scene, frame, frame.ray.spheres, unused), frame);
    std::vector<std::uint32_t> out(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 0u);
    forEachPixel(frame, [&](int x, int y, RayStatistics&) {
      out[static_cast<std::size_t>(y) * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(x)] = value(tracer, x, y);
    }, [](const RayStatistics&) {});
    return out;
  }

  // shade(x, y, statistics) on every pixel, tile by tile on the pool; each worker's statistics handed to merge once.
  template <class Shade, class Merge>
  void forEachPixel(const FrameInputs& frame, Shade&& shade, Merge&& merge) {
    const int columns = (frame.width + kTile - 1) / kTile, rows = (frame.height + kTile - 1) / kTile;
    const int tiles = columns * rows;
    std::atomic<int> next{0}, done{0};
    pool_.run([&](int worker) {
      RayStatistics local;
      for (int tile = next++; tile < tiles; tile = next++) {
        const int x0 = (tile % columns) * kTile, y0 = (tile / columns) * kTile;
        for (int y = y0; y < std::min(y0 + kTile, frame.height); ++y)
          for (int x = x0; x < std::min(x0 + kTile, frame.width); ++x) shade(x, y, local);
        const int finished = ++done;
        if (worker == 0 && progress_) progress_(static_cast<double>(finished) / static_cast<double>(tiles));  // the calling thread reports
      }
      merge(local);
    });
    if (progress_) progress_(1.0);  // the last tile may have been another worker's
  }

  ThreadPool pool_;
  RenderProgress progress_;
  std::vector<FrameInputs> sliceFrames_;            // motion blur: the frame at each shutter time
  std::vector<std::unique_ptr<TracedScene>> slices_;  // and its primitives
  FrameCheck check_;
  std::unique_ptr<TracedScene> traced_;
  ColorBuffer color_;
};

}  // namespace

std::unique_ptr<Renderer> makeRayRenderer(int threads, RenderProgress progress) { return std::make_unique<RayRenderer>(threads, std::move(progress)); }

void refuseRayImage(const FrameInputs& frame) {
  if (frame.areaAveraged)
    throw Error("settings key 'antialiasing.pattern': area is the CPU rasterizer's exact coverage; the ray tracer samples grid or jittered");
  if (frame.volume.placed)
    throw Error("settings key 'volume.mode': raycast is drawn by the CPU rasterizer (--backend cpu); the ray tracer draws splat and isosurface");
}

}  // namespace facet
