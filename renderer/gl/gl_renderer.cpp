#include "gl/gl_renderer.h"

#include <chrono>
#include <utility>

#include "common/error.h"
#include "common/stopwatch.h"
#include "gl/frame_renderer.h"
#include "gl/headless_context.h"
#include "pipeline/frame_checks.h"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

// What both renderers do with a frame, on whatever context is current.
class GlFrames {
 public:
  explicit GlFrames(const gl::GetProcAddress& getProcAddress) : frameRenderer_(getProcAddress) {}

  // The outputs asked, each from passes of its own in FrameOutput order.
  // `storage`: the renderer's recycled image, whose storage the read-back fills.
  RenderResult render(const Scene& scene, const FrameInputs& frame, const FrameOutputs& asked, Image storage) {
    check_(scene, frame);
    RenderResult result;
    Clock::time_point start = Clock::now();
    const bool uploaded = upload(scene);
    if (asked.has(FrameOutput::Image)) {  // the image's timings: the upload, its passes, the read-back
      if (uploaded) result.timings.push_back({kSceneUploadPass, millisecondsSince(start)});
      for (PassTiming& timing : frameRenderer_.drawFrame(scene, frame)) result.timings.push_back(std::move(timing));
      start = Clock::now();
      result.image = frameRenderer_.readImage(std::move(storage));
      result.timings.push_back({"read-back", millisecondsSince(start)});
    }
    if (asked.has(FrameOutput::TriangleIds)) result.triangleIds = frameRenderer_.drawTriangleIds(scene, frame);
    if (asked.has(FrameOutput::FragmentCounts)) result.fragmentCounts = frameRenderer_.drawFragmentCounts(frame);
    if (asked.has(FrameOutput::Depth)) result.depth = frameRenderer_.drawDepth(scene, frame);
    if (asked.has(FrameOutput::ShadowMaps)) result.shadowMaps = frameRenderer_.readShadowMaps(scene, frame);
    if (asked.has(FrameOutput::Normals)) result.normals = frameRenderer_.drawNormals(scene, frame);
    return result;
  }

  void forgetShadowMaps() { frameRenderer_.forgetShadowMaps(); }

  gl::GlFrameRenderer& frameRenderer() { return frameRenderer_; }
  const gl::GlFrameRenderer& frameRenderer() const { return frameRenderer_; }

 private:
  // Uploads the scene unless it is the one uploaded last (Scene::identity); true when it uploaded.
  bool upload(const Scene& scene) {
    if (scene.identity.is(uploaded_)) return false;
    frameRenderer_.uploadScene(scene);
    uploaded_ = scene.identity.token();
    return true;
  }

  FrameCheck check_;
  std::weak_ptr<const char> uploaded_;
  gl::GlFrameRenderer frameRenderer_;
};

class HeadlessGlRenderer final : public Renderer {
 public:
  explicit HeadlessGlRenderer(GlContextKind kind)
      : context_(gl::makeHeadlessContext(kind)),
        frames_(std::make_unique<GlFrames>([this](const char* name) { return context_->getProcAddress(name); })) {}

  // GL objects go while their context is current, then the context.
  ~HeadlessGlRenderer() override {
    try {
      context_->makeCurrent();
      frames_.reset();
    } catch (...) {  // a destructor must not throw; the process keeps running without the context
    }
  }

  std::string description() const override {
    return "gl: " + frames_->frameRenderer().rendererName() + " via " + std::string(context_->name());
  }

  RenderResult render(const Scene& scene, const FrameInputs& frame, const FrameOutputs& asked) override {
    context_->makeCurrent();  // another renderer of this process may have made its own current
    return frames_->render(scene, frame, asked, asked.has(FrameOutput::Image) ? recycledImage() : Image());
  }

  void forgetShadowMaps() override { frames_->forgetShadowMaps(); }

 private:
  std::unique_ptr<gl::HeadlessContext> context_;
  std::unique_ptr<GlFrames> frames_;
};

class CurrentContextGlRenderer final : public WindowGlRenderer {
 public:
  explicit CurrentContextGlRenderer(const gl::GetProcAddress& getProcAddress) : frames_(getProcAddress) {}

  std::string description() const override { return "gl: " + frames_.frameRenderer().rendererName() + " in the window's context"; }
  RenderResult render(const Scene& scene, const FrameInputs& frame, const FrameOutputs& asked) override {
    return frames_.render(scene, frame, asked, asked.has(FrameOutput::Image) ? recycledImage() : Image());
  }
  void forgetShadowMaps() override { frames_.forgetShadowMaps(); }
  unsigned framebuffer() const override { return frames_.frameRenderer().framebuffer(); }
  const std::string& rendererName() const override { return frames_.frameRenderer().rendererName(); }

 private:
  GlFrames frames_;
};

}  // namespace

std::unique_ptr<Renderer> makeGlRenderer(GlContextKind kind) { return std::make_unique<HeadlessGlRenderer>(kind); }

// Read in Mesa 22.3.6 and 25.0.7 (lp_setup_line.c, try_setup_line); the
// releases between are taken to have the later test, untested here.
LineEndTest lineEndTestOf(std::string_view driver) {
  const std::size_t at = driver.find("Mesa ");
  if (at == std::string_view::npos) return LineEndTest::Mesa25;
  int major = 0;
  for (std::size_t i = at + 5; i < driver.size() && driver[i] >= '0' && driver[i] <= '9'; ++i) major = 10 * major + (driver[i] - '0');
  return major > 0 && major <= 22 ? LineEndTest::Mesa22 : LineEndTest::Mesa25;
}

std::unique_ptr<WindowGlRenderer> makeWindowGlRenderer(const gl::GetProcAddress& getProcAddress) {
  return std::make_unique<CurrentContextGlRenderer>(getProcAddress);
}

void refuseCpuOnlyFrame(const FrameInputs& frame) {
  if (frame.hsr == HiddenSurface::Scanline)
    throw Error("settings key 'hsr': scanline is the CPU backend's scanline z-buffer (--backend cpu); OpenGL draws zbuffer or painter");
  if (frame.volume.placed)
    throw Error("settings key 'volume.mode': raycast is drawn by the CPU backend (--backend cpu); OpenGL draws splat and isosurface");
  if (frame.areaAveraged)
    throw Error("settings key 'antialiasing.pattern': area is the CPU backend's exact area-weighted averaging (--backend cpu); OpenGL samples grid or jittered");
}

}  // namespace facet
