// ReferenceWorker: the CPU reference on its own thread, newest request first.
#include <chrono>
#include <memory>
#include <thread>

#include <doctest/doctest.h>

#include "cpu/cpu_renderer.h"
#include "pipeline/frame_inputs.h"
#include "scene/primitives.h"
#include "viewer/reference_worker.h"

using namespace facet;
using namespace facet::viewer;

namespace {

std::shared_ptr<const Scene> cubeScene() {
  auto scene = std::make_shared<Scene>();
  scene->meshes.push_back(makeCube());
  scene->instances.push_back({0, glm::mat4(1.0f)});
  return scene;
}

ReferenceRequest request(std::uint64_t version, const std::shared_ptr<const Scene>& scene, int width, int height) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  ReferenceRequest r{version, scene, buildFrameInputs(*scene, settings), {}};
  r.glImage = makeCpuRenderer(1)->render(*scene, r.frame).image;  // stands in for the GL image
  return r;
}

// The worker's result, once it is idle; fails after a minute.
ReferenceResult waitForResult(ReferenceWorker& worker) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (worker.busy() && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::optional<ReferenceResult> result = worker.take();
  REQUIRE(result.has_value());
  return std::move(*result);
}

}  // namespace

TEST_CASE("a request comes back rendered and compared, with its version") {
  ReferenceWorker worker(1);
  worker.submit(request(7, cubeScene(), 64, 48));
  const ReferenceResult result = waitForResult(worker);
  CHECK(result.version == 7);
  CHECK(result.error.empty());
  CHECK(result.cpuImage.width() == 64);
  CHECK(result.heatMap.height() == 48);
  CHECK(result.cpuImage == result.glImage);  // the CPU renderer is deterministic
  CHECK(result.diff.maxDifference == 0);
  CHECK(result.diff.status == DiffStatus::Pass);
  CHECK_FALSE(worker.take().has_value());  // taken once
}

TEST_CASE("a newer request replaces one still waiting, and the newest result is the one left") {
  ReferenceWorker worker(1);
  const auto scene = cubeScene();
  for (std::uint64_t version = 1; version <= 4; ++version) worker.submit(request(version, scene, 96, 72));
  CHECK(waitForResult(worker).version == 4);
}

TEST_CASE("a render that fails comes back as an error, never past the thread") {
  ReferenceWorker worker(1);
  ReferenceRequest r = request(3, cubeScene(), 64, 48);
  r.glImage = Image(10, 10);  // compareImages refuses images of different sizes
  worker.submit(std::move(r));
  const ReferenceResult result = waitForResult(worker);
  CHECK(result.version == 3);
  CHECK(result.error.find("CPU reference: ") == 0);
  CHECK(result.cpuImage.empty());
}
