#pragma once
// The backend `facet render` and `facet batch` draw with, chosen by name.
// What they draw comes from the frame's spine (pipeline/frame_spine.h).
#include <memory>
#include <string>

#include "ray/ray_renderer.h"
#include "render/renderer.h"

namespace facet {

// The renderer `backend` names (gl, cpu, reference, ray, or auto: gl when a
// driver loads, cpu otherwise); `context` is gl's (auto: EGL, else OSMesa;
// egl; osmesa), `threads` the CPU backend's and ray tracer's (0: one per
// core). Throws facet::Error for gl when no driver loads or the build has
// none.
std::unique_ptr<Renderer> makeBackend(const std::string& backend, const std::string& context, int threads, RenderProgress progress = {});

// What the named backend (gl, reference or ray; cpu and auto draw every
// frame) refuses to draw of a frame's image, asked before it is made: the
// backend's own refusal, facet::Error naming the settings key.
void refuseUndrawnImage(const std::string& backend, const FrameInputs& frame);

}  // namespace facet
