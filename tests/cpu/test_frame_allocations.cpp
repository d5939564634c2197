// A CPU frame allocates nothing once its buffers have settled but what it
// returns: the image and its timing labels; and, given its last image back
// (Renderer::recycle), not the image either: it draws the same pixels into
// that storage. This binary counts every operator new of the process (its
// own main, so the count sees nothing else).
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "cpu/cpu_renderer.h"
#include "pipeline/frame_inputs.h"
#include "scene/default_scene.h"

namespace {
std::atomic<long> allocations{0}, allocatedBytes{0};
}

void* operator new(std::size_t n) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  allocatedBytes.fetch_add(static_cast<long>(n), std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

int main() {
  using namespace facet;
  const Scene scene = makeDefaultScene();
  int failures = 0;
  for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
    RenderSettings s;
    s.width = 320;
    s.height = 240;
    s.shading = mode;
    s.cullBackFaces = mode != ShadingMode::Gouraud;
    const FrameInputs frame = buildFrameInputs(scene, s);
    auto renderer = makeCpuRenderer(2);
    (void)renderer->render(scene, frame);  // the first frame sizes the buffers
    (void)renderer->render(scene, frame);
    const long before = allocations.load(), bytesBefore = allocatedBytes.load();
    const RenderResult result = renderer->render(scene, frame);
    const long count = allocations.load() - before, bytes = allocatedBytes.load() - bytesBefore;
    // The image (one buffer), the timings vector and its labels: what the
    // frame returns. Work handed to the threads goes by FunctionRef, never copied.
    const long imageBytes = static_cast<long>(result.image.width()) * result.image.height() * 4;
    const bool ok = count <= 8 && bytes <= imageBytes + 1024;
    std::printf("%s: mode %d: %ld allocations, %ld bytes (image %ld bytes)\n", ok ? "ok" : "FAIL", static_cast<int>(mode), count, bytes,
                imageBytes);
    failures += ok ? 0 : 1;
  }
  // Recycled: the tile-by-tile resolve (one sample) and the whole-buffer one (four samples).
  for (int samples : {1, 4}) {
    RenderSettings s;
    s.width = 320;
    s.height = 240;
    s.antialiasing.samples = samples;
    const FrameInputs frame = buildFrameInputs(scene, s);
    auto renderer = makeCpuRenderer(2);
    (void)renderer->render(scene, frame);
    RenderResult last = renderer->render(scene, frame);
    const Image expected = last.image;
    const Rgba8* const storage = last.image.data();
    renderer->recycle(std::move(last.image));
    const long before = allocations.load(), bytesBefore = allocatedBytes.load();
    const RenderResult result = renderer->render(scene, frame);
    const long count = allocations.load() - before, bytes = allocatedBytes.load() - bytesBefore;
    // (An anti-aliased frame copies its FrameInputs per sample: some kilobytes, far below the image's.)
    const long imageBytes = static_cast<long>(result.image.width()) * result.image.height() * 4;
    const bool ok = result.image.data() == storage && result.image == expected && bytes < imageBytes / 4;
    std::printf("%s: recycled, %d sample(s): %ld allocations, %ld bytes, %s storage, %s pixels\n", ok ? "ok" : "FAIL", samples, count, bytes,
                result.image.data() == storage ? "the same" : "other", result.image == expected ? "the same" : "other");
    failures += ok ? 0 : 1;
  }
  return failures == 0 ? 0 : 1;
}
