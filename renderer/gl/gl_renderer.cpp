#include "gl/gl_renderer.h"

#include <chrono>

#include "gl/frame_renderer.h"
#include "gl/headless_context.h"
#include "pipeline/frame_checks.h"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

class GlRenderer final : public Renderer {
 public:
  explicit GlRenderer(GlContextKind kind)
      : context_(gl::makeHeadlessContext(kind)),
        frameRenderer_(std::make_unique<gl::GlFrameRenderer>([this](const char* name) { return context_->getProcAddress(name); })) {}

  // GL objects go while their context is current, then the context.
  ~GlRenderer() override {
    try {
      context_->makeCurrent();
      frameRenderer_.reset();
    } catch (...) {  // a destructor must not throw; the process keeps running without the context
    }
  }

  std::string description() const override { return "gl: " + frameRenderer_->rendererName() + " via " + std::string(context_->name()); }

  std::vector<std::uint32_t> visibleTriangles(const Scene& scene, const FrameInputs& frame) override {
    check_(scene, frame);
    context_->makeCurrent();
    upload(scene);
    return frameRenderer_->drawTriangleIds(frame);
  }

  RenderResult render(const Scene& scene, const FrameInputs& frame) override {
    check_(scene, frame);
    context_->makeCurrent();  // another renderer of this process may have made its own current
    RenderResult result;
    Clock::time_point start = Clock::now();
    if (upload(scene)) result.timings.push_back({"scene upload", millisecondsSince(start)});
    for (PassTiming& timing : frameRenderer_->drawFrame(frame)) result.timings.push_back(std::move(timing));
    start = Clock::now();
    result.image = frameRenderer_->readImage();
    result.timings.push_back({"read-back", millisecondsSince(start)});
    return result;
  }

 private:
  // Uploads the scene unless it is the one uploaded last (Scene::identity); true when it uploaded.
  bool upload(const Scene& scene) {
    if (scene.identity.is(uploaded_)) return false;
    frameRenderer_->uploadScene(scene);
    uploaded_ = scene.identity.token();
    return true;
  }

  FrameCheck check_;
  std::weak_ptr<const char> uploaded_;
  std::unique_ptr<gl::HeadlessContext> context_;
  std::unique_ptr<gl::GlFrameRenderer> frameRenderer_;
};

}  // namespace

std::unique_ptr<Renderer> makeGlRenderer(GlContextKind kind) { return std::make_unique<GlRenderer>(kind); }

}  // namespace facet
