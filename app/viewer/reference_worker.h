#pragma once
// The CPU reference rasterizer (or the ray tracer) on a thread of its own, so that the window
// never waits for it. The viewer submits a frame (its FrameInputs and the
// image GlFrameRenderer drew from them) and keeps drawing; later it takes the
// result: the CPU image, the difference heat map and compareImages' figures.
//
// Only the newest request matters: one still waiting is replaced by the next
// (a render under way cannot be stopped, it runs to its end), and each result
// carries the version it was asked for, so that the viewer can drop it when
// the frame on screen has changed meanwhile.
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "compare/diff_result.h"
#include "compare/backend_agreement.h"
#include "image/image.h"
#include "pipeline/frame_inputs.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace facet::viewer {

struct ReferenceRequest {
  std::uint64_t version = 0;           // the viewer's frame version it was made for
  std::shared_ptr<const Scene> scene;  // shared: the viewer may load another scene meanwhile
  FrameInputs frame;
  Image glImage;                       // what GlFrameRenderer drew from frame
  bool rayTraced = false;              // compare with the ray tracer (renderer/ray) instead of the CPU rasterizer
};

struct ReferenceResult {
  std::uint64_t version = 0;
  Image glImage, cpuImage, heatMap;    // empty when the render failed
  DiffResult diff;                     // expected: the CPU image; actual: the GL image
  double milliseconds = 0;             // the CPU render alone
  std::string error;                   // non-empty: why the render failed
  bool rayTraced = false;              // cpuImage is the ray tracer's
  bool preview = false;                // one path a pixel, while the frame's ray.samples trace
};

class ReferenceWorker {
 public:
  // The CPU renderer's thread count (0: one per core).
  explicit ReferenceWorker(int threads);
  ReferenceWorker(const ReferenceWorker&) = delete;
  ReferenceWorker& operator=(const ReferenceWorker&) = delete;
  // Waits for a render under way to end.
  ~ReferenceWorker();

  void submit(ReferenceRequest request);
  bool busy() const;                       // a request waiting or rendering
  std::optional<ReferenceResult> take();   // the newest finished result, once

 private:
  void run();
  static ReferenceResult render(Renderer& renderer, const ReferenceRequest& request);
  Renderer& rendererFor(const ReferenceRequest& request);

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<ReferenceRequest> waiting_;
  std::optional<ReferenceResult> finished_;
  bool rendering_ = false;
  bool stop_ = false;
  std::unique_ptr<Renderer> renderer_;  // used on the worker thread only
  std::unique_ptr<Renderer> rayRenderer_;  // made there on the first ray-traced request
  int threads_;
  std::thread thread_;                  // last: it starts once the members above exist
};

}  // namespace facet::viewer
