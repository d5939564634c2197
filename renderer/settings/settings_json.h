#pragma once
// RenderSettings <-> JSON. Reading is strict: an unknown key, a value of the
// wrong type or out of range throws facet::Error naming the dotted key
// (e.g. "lights.0.intensity"). Keys absent from the JSON keep their defaults.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "settings/render_settings.h"

namespace facet {

nlohmann::json settingsToJson(const RenderSettings& settings);
RenderSettings settingsFromJson(const nlohmann::json& json);

// An emitter from a JSON object with particles.N's keys (a glTF node's
// extras.facet_particles); errors name `where` and the key.
Emitter emitterFromJson(const nlohmann::json& json, const std::string& where);

// Reads a settings file (JSON); errors name the file and the key.
RenderSettings loadSettingsFile(const std::string& path);

// Applies `key=value` (dotted key; value in JSON, or a bare string such as
// `gouraud`) to settings, e.g. "lights.0.position=[1,4,2]". An index one past
// the end of `lights` appends a light. Throws facet::Error naming the key.
void applySetting(RenderSettings& settings, const std::string& assignment);

}  // namespace facet
