#pragma once
// The settings controls, generated from the field table (settings_fields.h)
// by a visitor: each field gets a control chosen by its type and range, its
// help as a tooltip, and each group and each light a collapsing header. A
// field added to the table shows up here with no change to this file.
#include <string_view>

#include "pipeline/view_setup.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet::viewer {

// Draws the controls into the current ImGui window; true when one changed
// settings. An auto camera and auto lights show what auto chose for this
// scene, and editing one of their fields switches that source to manual,
// starting from the values shown (the rule settingsFor applies to --set).
bool drawSettingsPanel(RenderSettings& settings, const Scene& scene, const Sphere& sphere);

// The two halves of that rule:
// settings with an auto camera or auto lights replaced by what auto chose
// (the sources stay auto), for display;
RenderSettings shownSettings(const Scene& scene, const RenderSettings& settings);
// and what an edit of `shown`'s field `changedKey` (dotted, as --set writes
// it: "camera.eye", "lights.0.intensity") makes of settings. Editing
// camera.projection toggles it as the P key does, keeping an auto camera auto.
RenderSettings editedSettings(const RenderSettings& settings, const RenderSettings& shown, std::string_view changedKey,
                              const Sphere& sphere);

}  // namespace facet::viewer
