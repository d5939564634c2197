// The readable reference renderer: its frames drawn by the course's pipeline
// one triangle at a time (course_pipeline.cpp), then resolved one pixel at a
// time. It refuses what that pipeline does not draw.
#include "cpu/reference/reference_renderer.h"

#include <chrono>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/stopwatch.h"
#include "cpu/reference/course_pipeline.h"
#include "image/srgb.h"
#include "pipeline/frame_checks.h"
#include "shading/blending.h"
#include "shading/environment.h"

namespace facet {
namespace {

// The reference follows one triangle at a time through the z-buffer, its only hidden-surface removal, at the pixel centres.
void refuseHiddenSurface(const FrameInputs& frame) {
  if (!frame.samples.empty())
    throw Error("settings key 'antialiasing.samples': the reference backend draws one sample per pixel; --backend cpu and gl supersample");
  if (frame.hsr != HiddenSurface::ZBuffer)
    throw Error("settings key 'hsr': the reference backend has the z-buffer only; --backend cpu draws " +
                std::string(kHiddenSurfaceNames[static_cast<std::size_t>(frame.hsr)]));
}

using namespace cpu::reference;

class ReferenceRenderer final : public Renderer {
 public:
  std::string description() const override { return "cpu reference, one triangle at a time (renderer/cpu/reference)"; }

  // The image, triangle ids and fragment counts; the other stages are the fast renderer's.
  RenderResult render(const Scene& scene, const FrameInputs& frame, const FrameOutputs& asked) override {
    refuseUndrawn(asked, {FrameOutput::Image, FrameOutput::TriangleIds, FrameOutput::FragmentCounts});
    check_(scene, frame);
    if (asked.has(FrameOutput::Image)) refuseReferenceImage(frame);
    if (asked.has(FrameOutput::TriangleIds)) refuseHiddenSurface(frame);
    const auto start = std::chrono::steady_clock::now();
    const ShadowMaps maps = shadowPass(scene, frame);  // Gouraud lights its vertices with them, whatever is asked
    RenderResult result;
    if (asked.has(FrameOutput::Image)) {
      ColorBuffer color(frame.width, frame.height, glm::vec4(0.0f));
      for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) color.at(x, y) = backgroundPixel(frame, x, y);
      Target target = targetOf(frame);
      target.color = &color;
      litPass(scene, frame, maps, target, Drawn::Opaque);
      linePass(scene, frame, target);
      litPass(scene, frame, maps, target, Drawn::Blended);
      // The resolve, one pixel at a time.
      result.image = Image(frame.width, frame.height);
      for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) result.image.at(x, y) = encodePixel(unstored(color.at(x, y), frame.blending));
      result.timings.push_back({"both passes", millisecondsSince(start)});
    }
    if (asked.has(FrameOutput::TriangleIds)) {
      Target target = targetOf(frame);
      target.ids = &result.triangleIds.emplace(target.depth.size(), 0u);
      litPass(scene, frame, maps, target, Drawn::Opaque);  // blended triangles keep no pixel
    }
    if (asked.has(FrameOutput::FragmentCounts)) {
      Target target = targetOf(frame);
      target.counts = &result.fragmentCounts.emplace(target.depth.size(), 0u);
      litPass(scene, frame, maps, target, Drawn::All);
    }
    return result;
  }

 private:
  FrameCheck check_;

  static Target targetOf(const FrameInputs& frame) {
    return {frame.width, frame.height, std::vector<float>(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 1.0f)};
  }
};

}  // namespace

std::unique_ptr<Renderer> makeReferenceRenderer() { return std::make_unique<ReferenceRenderer>(); }

void refuseReferenceImage(const FrameInputs& frame) {
  refuseHiddenSurface(frame);
  if (frame.volume.placed)
    throw Error("settings key 'volume.mode': raycast is drawn by the CPU backend (--backend cpu); the readable reference draws splat and isosurface");
  if (frame.areaAveraged)
    throw Error("settings key 'antialiasing.pattern': area-weighted averaging is the CPU backend's (--backend cpu); the reference samples pixel centres");
}

}  // namespace facet
