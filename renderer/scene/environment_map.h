#pragma once
// The environment (reflection) map of renderer/PIPELINE.md, section 8: a
// cube map read from one PNG of six square faces side by side, loaded once
// with the scene, as the settings name it.
#include <string>

#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

// The cube map of a 6N × N strip read from `path`, with its mips and
// irradiance (PIPELINE.md, section 8); another shape is refused naming `path`.
EnvironmentMap environmentMapOf(Image strip, const std::string& path);

// The cube map in `path`: refused with a line naming the file when it does
// not decode or is not 6N × N.
EnvironmentMap loadEnvironmentMap(const std::string& path);

// Makes scene.environment the map `settings.map` names (none for an empty
// name), loading it only when the name changed; renews the scene's identity
// when the map changes. Errors name the key: "environment.map: sky.png: ...".
void useEnvironment(Scene& scene, const EnvironmentSettings& settings);

}  // namespace facet
