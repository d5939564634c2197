#pragma once
// `facet view`'s window and main loop (viewer_loop.cpp).
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "settings/render_settings.h"
#include "viewer/stage_view.h"
#include "viewer/viewer_state.h"

namespace facet::viewer {

struct ViewerOptions {
  std::shared_ptr<const Scene> scene;  // loaded by the command
  std::string scenePath;               // as given ("": the default scene), for the panel's field
  RenderSettings settings;             // --settings, --set and --size applied; width × height: the window
  std::string settingsPath;            // the panel's save / load field starts here
  std::string screenshotPath;          // -o: where F12 writes; empty: facet-view-N.png
  std::string batchScreenshot;         // --screenshot: draw `frames` frames, write the 3D view here, exit
  int frames = 3;
  bool screenshotWithPanel = false;    // --with-panel: the batch screenshot is the whole window
  bool followReference = false;        // --reference: the CPU reference follows every change
  bool rayReference = false;           // --ray-reference: the ray tracer is the reference
  FrameBackend backend = FrameBackend::Auto;  // --backend: what draws the 3D view
  bool showPanel = true;               // --no-panel: false
  int dragPreview = 2;                 // --drag-preview: ViewerState::dragPreview
  std::optional<std::array<int, 2>> pick;  // --pick X,Y: the pixel picked once the first frame is drawn (from the top left)
  std::vector<std::string> drops;      // --drop: files opened as if dropped on the window after the first frame
  std::string stage;                   // --stage: the stage shown over the view (render/stage.h names); empty: the frame
  StageSource stageSource = StageSource::OpenGl;  // --stage-source
  bool compareStages = false;          // --compare-stages: --screenshot also compares every stage between the backends
  std::string tab;                     // --tab: the panel's tab shown first
  int benchOrbit = 0;                  // --bench-orbit N: orbit once in N timed frames, print the figures (orbit_bench.h), exit
};

// Opens the window and runs until it closes (or, with batchScreenshot, until
// the screenshot is written); returns the exit code. Throws facet::Error when
// the window cannot open (no display, no OpenGL 4.5), and in batch mode when
// a frame cannot be drawn or written.
int runViewer(const ViewerOptions& options);

}  // namespace facet::viewer
