#pragma once
// What the viewer shows and what its panel and shortcuts edit: the scene, the
// settings of the next frame, the panel's file names and the last message.
// The window, the GL objects and the reference worker live in the loop.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "image/image.h"
#include "pipeline/view_setup.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet::viewer {

// Which backend draws the 3D view. auto: the CPU rasterizer where OpenGL is
// Mesa's software rasterizer (llvmpipe, softpipe: no GPU), which the CPU
// backend outruns, else OpenGL. Both draw the same bytes (the agreement suite).
enum class FrameBackend { Auto, OpenGl, Cpu, Count };
inline constexpr std::array<std::string_view, static_cast<std::size_t>(FrameBackend::Count)> kFrameBackendNames = {"auto", "gl", "cpu"};

// While a drag moves the camera, frames are drawn at 1/dragPreview of each
// side and shown scaled up; the frame at full size follows when the drag stops.
inline constexpr int kMaxDragPreview = 8;

struct ViewerState {
  std::shared_ptr<const Scene> scene;  // shared with the reference worker
  Sphere sphere;                        // of scene: the orbit's scale
  std::uint64_t sceneSerial = 0;        // counts scene loads: a new scene is a new frame
  RenderSettings settings;              // what the next frame draws
  RenderSettings startSettings;         // as the command line or the last settings file gave them:
                                        // R resets the camera to theirs, a new scene starts with their camera and lights

  std::string scenePath;                // the panel's text fields
  std::string settingsPath;
  std::string screenshotPath;           // empty: facet-view-N.png, the first N not taken

  bool playing = false;                 // the animation plays: settings.time advances with the clock (space)
  FrameBackend backend = FrameBackend::Auto;
  int dragPreview = 2;                  // 1: full size while dragging too; at most kMaxDragPreview

  std::string openTab;                  // the panel's tab to bring forward once (--tab), then empty
  std::vector<std::string> recentFiles; // scenes and settings files opened, newest first (the Files tab)

  std::string message;                  // the last action's outcome, shown in the panel (an error also on stderr)
  bool messageIsError = false;
};

void setScene(ViewerState& state, std::shared_ptr<const Scene> scene);

// Each action reports in state.message, and never throws on bad input: a
// broken glTF file or settings file leaves the scene and settings as they were.
// A scene that loads gets the camera and lights of startSettings (an auto
// camera frames the new scene, not the old one's view).
bool loadSceneFile(ViewerState& state, const std::string& path);
void loadSettings(ViewerState& state);
// A file dropped on the window: a .json is a settings file, anything else a scene.
void openDroppedFile(ViewerState& state, const std::string& path);
void saveSettings(ViewerState& state);
// image: the 3D frame without the panel.
void saveScreenshot(ViewerState& state, const Image& image);

// facet-view-1.png, facet-view-2.png, ...: the first that does not exist yet.
std::string nextScreenshotName();

}  // namespace facet::viewer
