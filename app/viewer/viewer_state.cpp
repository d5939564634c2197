#include "viewer/viewer_state.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/atomic_file.h"
#include "common/error.h"
#include "image/png.h"
#include "scene/load_scene.h"
#include "settings/settings_json.h"

namespace facet::viewer {
namespace {

// How many files the Files tab lists.
constexpr std::size_t kRecentFiles = 8;

void report(ViewerState& state, std::string message, bool isError) {
  if (isError) std::fprintf(stderr, "facet: view: %s\n", message.c_str());
  state.message = std::move(message);
  state.messageIsError = isError;
}

void remember(ViewerState& state, const std::string& path) {
  std::erase(state.recentFiles, path);
  state.recentFiles.insert(state.recentFiles.begin(), path);
  if (state.recentFiles.size() > kRecentFiles) state.recentFiles.resize(kRecentFiles);
}

}  // namespace

void setScene(ViewerState& state, std::shared_ptr<const Scene> scene) {
  state.sphere = sceneSphere(*scene);
  state.scene = std::move(scene);
  ++state.sceneSerial;
}

bool loadSceneFile(ViewerState& state, const std::string& path) {
  try {
    auto scene = std::make_shared<const Scene>(loadScene(path));
    const std::size_t warnings = scene->warnings.size();
    setScene(state, std::move(scene));
    state.scenePath = path;
    state.settings.camera = state.startSettings.camera;
    state.settings.lightSource = state.startSettings.lightSource;
    state.settings.lights = state.startSettings.lights;
    remember(state, path);
    report(state, "loaded " + state.scene->source + (warnings ? " (" + std::to_string(warnings) + " loader warnings)" : ""), false);
    return true;
  } catch (const Error& e) {
    report(state, e.what(), true);
  } catch (const std::bad_alloc&) {
    report(state, path + ": out of memory", true);
  } catch (const std::exception& e) {  // whatever the loader lets through: shown, never fatal
    report(state, path + ": " + e.what(), true);
  }
  return false;
}

void loadSettings(ViewerState& state) {
  try {
    state.settings = state.startSettings = loadSettingsFile(state.settingsPath);
    remember(state, state.settingsPath);
    report(state, "settings loaded from " + state.settingsPath, false);
  } catch (const Error& e) {
    report(state, e.what(), true);
  }
}

void openDroppedFile(ViewerState& state, const std::string& path) {
  if (std::filesystem::path(path).extension() == ".json") {
    state.settingsPath = path;
    loadSettings(state);
  } else {
    state.scenePath = path;
    loadSceneFile(state, path);
  }
}

void saveSettings(ViewerState& state) {
  try {
    // The same text as `facet settings -o`, which `facet render --settings` reads.
    const std::string text = settingsToJson(state.settings).dump(2) + "\n";
    writeFileAtomically(state.settingsPath, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
    report(state, "settings saved to " + state.settingsPath, false);
  } catch (const Error& e) {
    report(state, e.what(), true);
  }
}

void saveScreenshot(ViewerState& state, const Image& image) {
  const std::string path = state.screenshotPath.empty() ? nextScreenshotName() : state.screenshotPath;
  try {
    writePng(path, image);
    report(state, "screenshot written to " + path, false);
  } catch (const Error& e) {
    report(state, e.what(), true);
  } catch (const OutOfMemory& e) {  // shown, as any failed screenshot: the window stays
    report(state, std::string("out of memory while ") + e.what(), true);
  }
}

std::string nextScreenshotName() {
  for (int n = 1;; ++n) {
    std::string name = "facet-view-" + std::to_string(n) + ".png";
    std::error_code ec;
    if (!std::filesystem::exists(name, ec)) return name;
  }
}

}  // namespace facet::viewer
