#pragma once
// The 3D frame on screen: drawn by OpenGL on the window's context or by the
// CPU rasterizer (ViewerState::backend), only when the scene or the settings
// changed, at reduced size while a drag moves the camera, and blitted into
// the part of the window beside the panel.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "gl/gl_renderer.h"
#include "image/image.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/frame_spine.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "viewer/image_texture.h"
#include "gl/gl_functions.h"
#include "viewer/viewer_state.h"

namespace facet::viewer {

// Where the 3D view sits in the window's framebuffer: x from the left, y from the bottom.
struct ViewRect {
  int x = 0, y = 0, width = 0, height = 0;
};

// The frame last drawn.
struct DrawnFrame {
  std::uint64_t version = 0;           // counts the distinct frames drawn; 0: none yet
  std::string key;                     // what it was drawn from (scene, settings, size), or failed to draw from
  std::shared_ptr<const Scene> scene;  // the scene `frame` was built from
  FrameInputs frame;
  Image image;                         // what the backend drew
  bool onCpu = false;                  // the CPU rasterizer drew it, not OpenGL
  bool preview = false;                // drawn at 1/dragPreview of the view's size during a drag
  double milliseconds = 0;             // the frame's passes (shadow, lit, resolve; not the read-back), when it last ran
  std::string error;                   // why the newest settings could not be drawn; the last good image stays
};

class ViewFrame {
 public:
  // gl and glRenderer must outlive the view. cpuThreads: the CPU rasterizer's (0: one per core).
  ViewFrame(const gl::GlFunctions& gl, WindowGlRenderer& glRenderer, int cpuThreads);

  // Whether `backend` draws on the CPU here (auto: where OpenGL is a software rasterizer).
  bool drawsOnCpu(FrameBackend backend) const;
  // One line for the panel: which backend draws the view, and why when auto chose.
  std::string backendLine(FrameBackend backend) const;

  // Draws the frame of `state` when it differs from the one on screen (or
  // always, with force); true when it tried. preview: draw at 1/dragPreview size.
  bool drawIfChanged(const ViewerState& state, bool preview, bool force);
  const DrawnFrame& drawn() const { return drawn_; }
  WindowGlRenderer& glRenderer() { return glRenderer_; }
  Renderer& cpuRenderer() { return *cpuRenderer_; }
  // OpenGL drew something else into its framebuffer (a stage, triangle
  // ids): when it draws the view, the next drawIfChanged draws the same
  // frame again, under the same version.
  void invalidate() {
    if (!drawn_.onCpu) redraw_ = true;
  }

  // The OpenGL image of the frame on screen, for the reference's comparison:
  // the one on screen, or drawn by OpenGL now when the CPU drew it.
  Image glImage();

  // The frame into `view` of the window's framebuffer (scaled when it is a
  // preview or the window was just resized); the rest of the window black.
  void blit(int windowWidth, int windowHeight, ViewRect view) const;

 private:
  const gl::GlFunctions& gl_;
  WindowGlRenderer& glRenderer_;
  std::unique_ptr<Renderer> cpuRenderer_;
  ImageTexture cpuTexture_;  // the CPU frame, for the blit
  bool softwareGl_;          // GL_RENDERER names Mesa's llvmpipe or softpipe
  DrawnFrame drawn_;
  bool redraw_ = false;      // invalidate()
  Image glImage_;            // glImage()'s, for drawn_.version
  std::uint64_t glImageVersion_ = 0;
  // What the frames are drawn from (pipeline/frame_spine.h), over the scenes the viewer loads: the files
  // the settings name (the maps, the volume) are read once, the sprites added again for each frame.
  std::optional<FrameSpine> spine_;
};

}  // namespace facet::viewer
