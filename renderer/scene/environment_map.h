#pragma once
// The environment (reflection) map of renderer/PIPELINE.md, "Textures": a
// cube map read from one PNG of six square faces side by side, as the
// settings name it (pipeline/frame_spine.h reads it once and puts it in the
// frame's scene).
#include <string>

#include "scene/scene.h"

namespace facet {

// The cube map of a 6N × N strip read from `path`, with its mips and
// irradiance (PIPELINE.md, "Textures"); another shape is refused naming `path`.
EnvironmentMap environmentMapOf(Image strip, const std::string& path);

// The cube map in `path`: refused with a line naming the file when it does
// not decode or is not 6N × N.
EnvironmentMap loadEnvironmentMap(const std::string& path);

}  // namespace facet
