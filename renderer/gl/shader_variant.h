#pragma once
// Lit-pass programs specialized per frame: what the shaders would otherwise
// decide per pixel from uniforms (light count and kinds, which lights have
// shadow maps, the specular model, the PCF radius, whether the draw is
// textured) becomes #defines compiled in. llvmpipe evaluates both sides of
// every `if` with per-pixel masks, so a texture path or a shadow lookup that
// a uniform turns off still costs its full price on every pixel; compiled
// out, it costs nothing. Only dead branches go: the arithmetic of the path
// taken is unchanged, and the images are bit-identical.
#include <string>

#include "pipeline/frame_inputs.h"

namespace facet::gl {

// The #define lines (one per macro, each ending in a newline) of the lit
// programs for `frame`, for draws with (textured) or without a base colour
// texture. Equal strings mean the same program, so the text is also the key
// of the renderer's program cache.
std::string litShaderDefines(const FrameInputs& frame, bool textured);

}  // namespace facet::gl
