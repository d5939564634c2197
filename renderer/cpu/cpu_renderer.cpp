#include "cpu/cpu_renderer.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "cpu/lighting.h"
#include "cpu/passes.h"

namespace facet {
namespace {

// Runs work(rowBegin, rowEnd) on `threads` bands of [0, rows). Each band is a
// disjoint set of rows, so every pixel has one writer.
void inBands(int threads, int rows, const std::function<void(int, int)>& work) {
  const int bands = std::max(1, std::min(threads, rows));
  if (bands == 1) {
    work(0, rows);
    return;
  }
  std::vector<std::thread> pool;
  for (int b = 0; b < bands; ++b) pool.emplace_back(work, rows * b / bands, rows * (b + 1) / bands);
  for (std::thread& t : pool) t.join();
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

class CpuRenderer final : public Renderer {
 public:
  explicit CpuRenderer(int threads)
      : threads_(threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()))) {}

  std::string description() const override { return "cpu reference rasterizer, " + std::to_string(threads_) + " thread(s)"; }

  RenderResult render(const Scene& scene, const FrameInputs& frame) override {
    RenderResult result;
    cpu::ShadowMaps maps;
    if (frame.shadowLayerCount > 0) {
      const auto start = std::chrono::steady_clock::now();
      maps.reset(frame.shadows.mapSize, frame.shadowLayerCount);
      for (std::size_t l = 0; l < frame.lights.size(); ++l) {
        const FrameLight& light = frame.lights[l];
        if (!light.hasShadowMap) continue;
        for (int face = 0; face < light.frustum.faceCount; ++face)
          inBands(threads_, maps.size, [&](int begin, int end) { cpu::shadowPass(scene, frame, light, face, begin, end, maps); });
      }
      result.timings.push_back({"shadow pass (" + std::to_string(frame.shadowLayerCount) + " maps)", millisecondsSince(start)});
    }

    const auto start = std::chrono::steady_clock::now();
    const glm::vec3 background = cpu::encodeSrgb(frame.background);
    result.image = Image(frame.width, frame.height, {cpu::quantize(background.r), cpu::quantize(background.g), cpu::quantize(background.b), 255});
    std::vector<float> depth(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 1.0f);
    inBands(threads_, frame.height, [&](int begin, int end) { cpu::litPass(scene, frame, maps, begin, end, result.image, depth); });
    result.timings.push_back({"lit pass", millisecondsSince(start)});
    return result;
  }

 private:
  int threads_;
};

}  // namespace

std::unique_ptr<Renderer> makeCpuRenderer(int threads) { return std::make_unique<CpuRenderer>(threads); }

}  // namespace facet
