#include "viewer/view_frame.h"

#include <algorithm>
#include <utility>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "cpu/cpu_renderer.h"
#include "settings/settings_json.h"

namespace facet::viewer {
namespace {

bool isSoftwareRasterizer(const std::string& glRenderer) {
  return glRenderer.find("llvmpipe") != std::string::npos || glRenderer.find("softpipe") != std::string::npos;
}

}  // namespace

ViewFrame::ViewFrame(const gl::GlFunctions& gl, WindowGlRenderer& glRenderer, int cpuThreads)
    : gl_(gl), glRenderer_(glRenderer), cpuRenderer_(makeCpuRenderer(cpuThreads)), cpuTexture_(gl),
      softwareGl_(isSoftwareRasterizer(glRenderer.rendererName())) {}

bool ViewFrame::drawsOnCpu(FrameBackend backend) const {
  return backend == FrameBackend::Cpu || (backend == FrameBackend::Auto && softwareGl_);
}

std::string ViewFrame::backendLine(FrameBackend backend) const {
  const std::string shown = drawsOnCpu(backend) ? "the " + cpuRenderer_->description() : "OpenGL";
  if (backend != FrameBackend::Auto) return "3D view by " + shown;
  return "3D view by " + shown + (softwareGl_ ? ": auto, OpenGL here is a software rasterizer" : ": auto, OpenGL here has a GPU");
}

bool ViewFrame::drawIfChanged(const ViewerState& state, bool preview, bool force) {
  RenderSettings settings = state.settings;
  const int divisor = preview ? std::clamp(state.dragPreview, 1, kMaxDragPreview) : 1;
  settings.width = std::max(1, (settings.width + divisor - 1) / divisor);
  settings.height = std::max(1, (settings.height + divisor - 1) / divisor);
  const bool onCpu = drawsOnCpu(state.backend);
  // Everything the frame depends on: the scene, the backend and the settings (the size included).
  const std::string key = std::to_string(state.sceneSerial) + (onCpu ? " cpu " : " gl ") + settingsToJson(settings).dump();
  if (std::exchange(redraw_, false)) force = true;
  if (key == drawn_.key && !force) return false;
  try {
    // The spine keeps the files it read and the scenes it made while the settings name the same; sprites face each frame's camera.
    if (!spine_) spine_.emplace(state.scene);
    else if (spine_->loaded() != state.scene) spine_->setLoaded(state.scene);
    PreparedFrame prepared = spine_->frame(settings);
    Renderer& renderer = onCpu ? *cpuRenderer_ : static_cast<Renderer&>(glRenderer_);
    RenderResult result = renderer.render(*prepared.scene, prepared.inputs);
    drawn_.milliseconds = 0;
    for (const PassTiming& t : result.timings)
      if (t.pass != "read-back") drawn_.milliseconds += t.milliseconds;
    if (key != drawn_.key || drawn_.version == 0) ++drawn_.version;
    drawn_.scene = std::move(prepared.scene);
    drawn_.frame = std::move(prepared.inputs);
    renderer.recycle(std::exchange(drawn_.image, std::move(result.image)));  // the last frame's storage holds the next
    drawn_.onCpu = onCpu;
    drawn_.preview = divisor > 1;
    if (onCpu) cpuTexture_.upload(drawn_.image);
    drawn_.error.clear();
  } catch (const Error& e) {
    drawn_.error = e.what();
  }
  drawn_.key = key;
  return true;
}

Image ViewFrame::glImage() {
  if (!drawn_.onCpu || drawn_.version == 0) return drawn_.image;
  if (glImageVersion_ != drawn_.version) {
    glImageVersion_ = drawn_.version;
    try {
      glImage_ = glRenderer_.render(*drawn_.scene, drawn_.frame).image;
    } catch (const Error&) {
      glImage_ = Image();  // OpenGL cannot draw this frame (volume ray casting): nothing to compare
    }
  }
  return glImage_;
}

void ViewFrame::blit(int windowWidth, int windowHeight, ViewRect view) const {
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  gl_.Disable(GL_SCISSOR_TEST);  // a blit honours the scissor box
  gl_.Viewport(0, 0, windowWidth, windowHeight);
  const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  gl_.ClearNamedFramebufferfv(0, GL_COLOR, 0, black);
  if (drawn_.version == 0) return;
  const unsigned source = drawn_.onCpu ? cpuTexture_.framebuffer() : glRenderer_.framebuffer();
  gl_.BlitNamedFramebuffer(source, 0, 0, 0, drawn_.frame.width, drawn_.frame.height, view.x, view.y, view.x + view.width, view.y + view.height,
                             GL_COLOR_BUFFER_BIT, drawn_.preview ? GL_LINEAR : GL_NEAREST);
}

}  // namespace facet::viewer
