#include "viewer/reference_worker.h"

#include <chrono>
#include <exception>
#include <new>
#include <utility>

#include "common/stopwatch.h"
#include "compare/heat_map.h"
#include "compare/image_diff.h"
#include "cpu/cpu_renderer.h"
#include "ray/ray_renderer.h"

namespace facet::viewer {

ReferenceWorker::ReferenceWorker(int threads) : renderer_(makeCpuRenderer(threads)), threads_(threads), thread_([this] { run(); }) {}

Renderer& ReferenceWorker::rendererFor(const ReferenceRequest& request) {
  if (!request.rayTraced) return *renderer_;
  if (!rayRenderer_) rayRenderer_ = makeRayRenderer(threads_);
  return *rayRenderer_;
}

ReferenceWorker::~ReferenceWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void ReferenceWorker::submit(ReferenceRequest request) {
  {
    std::lock_guard lock(mutex_);
    waiting_ = std::move(request);
  }
  wake_.notify_one();
}

bool ReferenceWorker::busy() const {
  std::lock_guard lock(mutex_);
  return rendering_ || waiting_.has_value();
}

std::optional<ReferenceResult> ReferenceWorker::take() {
  std::lock_guard lock(mutex_);
  return std::exchange(finished_, std::nullopt);
}

void ReferenceWorker::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stop_ || waiting_.has_value(); });
    if (stop_) return;
    const ReferenceRequest request = std::move(*std::exchange(waiting_, std::nullopt));
    rendering_ = true;
    lock.unlock();
    ReferenceResult result;
    try {
      Renderer& renderer = rendererFor(request);
      // The ray tracer refines: one path a pixel first, shown while the frame's ray.samples trace.
      if (request.rayTraced && request.frame.ray.samples > 1) {
        ReferenceRequest preview = request;
        preview.frame.ray.samples = 1;
        ReferenceResult first = render(renderer, preview);
        first.preview = true;
        lock.lock();
        finished_ = std::move(first);
        const bool newer = waiting_.has_value();
        lock.unlock();
        if (newer) {  // the frame changed meanwhile: the full render would be dropped
          lock.lock();
          rendering_ = false;
          continue;
        }
      }
      result = render(renderer, request);
    } catch (const std::exception& e) {  // the ray tracer's pool could not start
      result = ReferenceResult{request.version, {}, {}, {}, {}, 0, std::string("ray tracer: ") + e.what(), true};
    }
    lock.lock();
    rendering_ = false;
    finished_ = std::move(result);
  }
}

ReferenceResult ReferenceWorker::render(Renderer& renderer, const ReferenceRequest& request) {
  ReferenceResult result;
  result.version = request.version;
  result.rayTraced = request.rayTraced;
  const std::string who = request.rayTraced ? "ray tracer: " : "CPU reference: ";
  try {
    const auto start = std::chrono::steady_clock::now();
    Image cpuImage = renderer.render(*request.scene, request.frame).image;
    result.milliseconds = millisecondsSince(start);
    result.diff = compareImages(cpuImage, request.glImage, backendAgreement());
    result.heatMap = heatMap(cpuImage, request.glImage, backendAgreement());
    result.cpuImage = std::move(cpuImage);
    result.glImage = request.glImage;
  } catch (const std::bad_alloc&) {
    result = ReferenceResult{request.version, {}, {}, {}, {}, 0, who + "out of memory", request.rayTraced};
  } catch (const std::exception& e) {  // facet::Error and anything else: shown in the panel, never past the thread
    result = ReferenceResult{request.version, {}, {}, {}, {}, 0, who + e.what(), request.rayTraced};
  }
  return result;
}

}  // namespace facet::viewer
