// Running out of memory on a CPU worker thread (binning, the vertex stage,
// a tile's buffers) is reported to the caller of render() like any other
// error, instead of std::terminate. This binary replaces operator new so that
// it fails on every thread but the one that calls render().
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <thread>

#include "cpu/cpu_renderer.h"
#include "common/thread_pool.h"
#include "pipeline/frame_inputs.h"
#include "scene/default_scene.h"

namespace {
std::atomic<bool> failOnWorkers{false};
std::atomic<long> refused{0};
std::thread::id mainThread;
}

void* operator new(std::size_t n) {
  if (failOnWorkers.load(std::memory_order_relaxed) && std::this_thread::get_id() != mainThread) {
    refused.fetch_add(1, std::memory_order_relaxed);
    throw std::bad_alloc();
  }
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

int main() {
  using namespace facet;
  mainThread = std::this_thread::get_id();
  int failures = 0;
  const auto check = [&](bool ok, const char* what) {
    std::printf("%s: %s\n", ok ? "ok" : "FAIL", what);
    failures += ok ? 0 : 1;
  };

  // The pool itself: an exception on worker 1 reaches run()'s caller once
  // every worker has finished, and the pool runs the next job normally.
  {
    ThreadPool pool(2);
    std::atomic<int> finished{0};
    bool caught = false;
    try {
      pool.run([&](int worker) {
        if (worker == 1) throw std::runtime_error("worker 1 failed");
        finished.fetch_add(1);
      });
    } catch (const std::runtime_error& e) {
      caught = std::string(e.what()) == "worker 1 failed";
    }
    check(caught && finished.load() == 1, "an exception on a pool worker reaches the caller of run");
    finished = 0;
    pool.run([&](int) { finished.fetch_add(1); });
    check(finished.load() == 2, "the pool runs the next job on every worker");
  }

  // A whole frame: a fresh renderer's first frame sizes its bins and buffers
  // on the worker threads, where every allocation now fails.
  const Scene scene = makeDefaultScene();
  RenderSettings s;
  s.width = 320;
  s.height = 240;
  const FrameInputs frame = buildFrameInputs(scene, s);
  auto renderer = makeCpuRenderer(2);
  failOnWorkers = true;
  bool caught = false;
  try {
    (void)renderer->render(scene, frame);
  } catch (const std::bad_alloc&) {
    caught = true;
  }
  failOnWorkers = false;
  std::printf("allocations refused on worker threads: %ld\n", refused.load());
  check(refused.load() > 0, "the frame allocates on a worker thread (else this test tests nothing)");
  check(caught, "std::bad_alloc on a worker thread reaches the caller of render");
  const RenderResult result = renderer->render(scene, frame);
  check(result.image.width() == 320, "the renderer draws the next frame once memory is back");
  return failures == 0 ? 0 : 1;
}
