#pragma once
// The OpenGL backend behind facet::Renderer: GlFrameRenderer drawing each
// frame into an offscreen framebuffer, on a headless context of its own
// (facet render, the tests) or on a context the caller owns (the viewer's
// window). Both are the same Renderer: a scene is checked and uploaded once
// (Scene::identity), each frame checked, drawn and read back.
#include <memory>
#include <string>
#include <string_view>

#include "gl/get_proc_address.h"
#include "pipeline/frame_inputs.h"
#include "render/renderer.h"

namespace facet {

enum class GlContextKind { OsMesa, Egl };

// Creates the context and loads OpenGL; throws facet::Error (library missing,
// no 4.5 core context).
std::unique_ptr<Renderer> makeGlRenderer(GlContextKind kind);

// The segment-end test of the llvmpipe a driver string names (a GL_VERSION,
// or a renderer's description, "... 4.5 (Core Profile) Mesa 22.3.6"): Mesa
// 22 and older decide by signs, later releases by the quad's edges
// (pipeline/frame_inputs.h). A string without a Mesa version gets the newest.
LineEndTest lineEndTestOf(std::string_view driver);

// What OpenGL refuses of a frame (the CPU backend's own algorithms: the
// scanline z-buffer, area-weighted averaging), naming the key: every draw
// checks it, and `facet render` before it loads the driver.
void refuseCpuOnlyFrame(const FrameInputs& frame);

// The same backend on the caller's context, which must be current for every
// call: what the viewer draws its window's frames with.
class WindowGlRenderer : public Renderer {
 public:
  // The framebuffer render() drew into (colour attachment 0): it keeps the
  // last frame, for the window to blit from.
  virtual unsigned framebuffer() const = 0;
  // GL_RENDERER and GL_VERSION.
  virtual const std::string& rendererName() const = 0;
};

// Loads OpenGL through getProcAddress; throws facet::Error without 4.5 core.
std::unique_ptr<WindowGlRenderer> makeWindowGlRenderer(const gl::GetProcAddress& getProcAddress);

}  // namespace facet
