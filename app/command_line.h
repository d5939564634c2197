#pragma once
// The shape every facet subcommand shares: the scene file as the positional
// argument (none: the default scene), --settings FILE.json, --set key=value
// (repeatable), --size WxH, the camera moves --camera-azimuth,
// --camera-elevation and --camera-zoom, -o/--output FILE.
#include <array>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "pipeline/camera_orbit.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

struct CommonOptions {
  std::string scenePath;              // empty: the default scene
  std::string settingsPath;           // empty: default settings
  std::vector<std::string> assignments;  // --set key=value, in order
  std::string size;                   // WxH, empty: from settings
  std::string output;                 // -o
  CameraOrbit orbit;                  // --camera-azimuth, --camera-elevation, --camera-zoom
};

void addCommonOptions(CLI::App& command, CommonOptions& options, const std::string& outputHelp);

// The settings a command runs with: the file (or the defaults), then each
// --set in order, then --size. A --set of a camera or light key while that
// source is auto first fixes the camera or lights where auto put them for
// this scene, then changes the key. Last, a camera move (--camera-azimuth,
// -elevation, -zoom) turns the camera these settings resolve to (auto: the
// scene's or the fitted one) and leaves it manual, as a --set of camera.eye would.
RenderSettings settingsFor(const CommonOptions& options, const Scene& scene);
// The same from `base` (a settings file's, a batch job's object), the
// assignments and the size ("" none) given apart.
RenderSettings settingsFor(RenderSettings base, const std::vector<std::string>& assignments, const std::string& size, const Scene& scene);

// Parses "WxH" (1..kMaxImageSide each) or throws facet::UsageError.
void parseSize(const std::string& text, int& width, int& height);

// Parses a pixel "X,Y" (whole numbers from 0, counted from the top left) or
// throws facet::UsageError naming `option`; the frame checks the range.
std::array<int, 2> parsePixel(const std::string& text, const std::string& option);

// An option's check that its value is a whole number in [min, max], with a
// message that says which of the two it is not (CLI::Range says "not in
// range" for "abc" too).
CLI::Validator wholeNumberIn(int min, int max);

// The same for a real number in [min, max] (nan and inf are not numbers).
CLI::Validator numberIn(double min, double max);

}  // namespace facet
