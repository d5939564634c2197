#pragma once
// The backend `facet render` and `facet batch` draw with, chosen by name.
// What they draw comes from the frame's spine (pipeline/frame_spine.h).
#include <memory>
#include <string>

#include "ray/ray_renderer.h"
#include "render/renderer.h"

namespace facet {

// The renderer `backend` names (gl, cpu, reference, ray); `context` is gl's
// (osmesa or egl), `threads` the CPU backend's and ray tracer's (0: one per
// core). Throws facet::Error for gl in a build without it.
std::unique_ptr<Renderer> makeBackend(const std::string& backend, const std::string& context, int threads, RenderProgress progress = {});

}  // namespace facet
