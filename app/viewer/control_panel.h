#pragma once
// The viewer's panel: what is on screen and how fast it draws, then tabs for
// the settings (settings_panel.h), files, the CPU reference and help.
#include <cstddef>
#include <cstdint>
#include <string>

#include "viewer/matrices_tab.h"
#include "viewer/pixel_pick.h"
#include "viewer/stage_view.h"
#include "viewer/reference_view.h"
#include "viewer/viewer_state.h"

namespace facet::viewer {

struct FrameStats {
  std::string renderer;            // GL_RENDERER, GL_VERSION
  std::string backend;             // which backend draws the 3D view, and why (ViewFrame::backendLine)
  double drawMilliseconds = 0;     // the 3D frame's passes, median of the last 60 frames drawn
  double windowMilliseconds = 0;   // a whole window frame (UI, 3D if it changed, swap), median of the last 60
  std::size_t triangles = 0;       // over all instances
  int lights = 0, shadowMaps = 0;  // of the frame on screen
  std::uint64_t version = 0;       // of the frame on screen, for the reference view
  std::string drawError;           // why the current settings cannot be drawn; the screen keeps the last frame that could
};

struct PanelRequests {
  bool screenshot = false;
};

// Within an ImGui frame: the panel docked on the left of the window, the
// whole height, `width` wide (ImGui units; the user's resize of its right
// edge comes back in it). redrawEveryFrame: the panel's checkbox (draw the
// 3D frame even when nothing changed, to time it).
PanelRequests drawControlPanel(ViewerState& state, const FrameStats& stats, ReferenceView& reference, PixelPick& pick, ViewFrame& view,
                               StageView& stages, MatrixSelection& matrices, bool& redrawEveryFrame, float& width);

}  // namespace facet::viewer
