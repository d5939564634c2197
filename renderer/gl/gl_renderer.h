#pragma once
// The OpenGL backend behind facet::Renderer, headless: a context of the given
// kind, and GlFrameRenderer drawing each frame into an offscreen framebuffer.
#include <memory>

#include "render/renderer.h"

namespace facet {

enum class GlContextKind { OsMesa, Egl };

// Creates the context and loads OpenGL; throws facet::Error (library missing,
// no 4.5 core context).
std::unique_ptr<Renderer> makeGlRenderer(GlContextKind kind);

}  // namespace facet
