#pragma once
// The mouse and the keys over the 3D view, where ImGui does not want them:
// left drag orbits around P_ref, right or middle drag pans, the wheel zooms
// (an auto camera is made manual first, from what auto chose), and the
// shortcuts of the Help tab.
#include <vector>

#include "viewer/viewer_state.h"
#include "viewer/viewer_window.h"

namespace facet::viewer {

// What the loop does for a shortcut, beyond editing the settings.
struct ViewRequests {
  bool screenshot = false;   // F12, Ctrl+S
  bool quit = false;         // Esc
  bool togglePanel = false;  // H
  bool cameraMoved = false;  // a drag or the wheel moved the camera this frame
  bool picked = false;       // a left click on the view without a drag: pick the pixel at pickX, pickY
  float pickX = 0, pickY = 0;  // ImGui units, from the window's top left
};

class ViewInput {
 public:
  // Within an ImGui frame; keys: pressed since the last frame. viewLeft:
  // where the 3D view starts (ImGui units; the panel is left of it).
  ViewRequests update(ViewerState& state, const std::vector<KeyPress>& keys, float viewLeft);

 private:
  int dragButton_ = -1;  // the button that started a drag over the view; -1: none
  float dragDistance_ = 0;  // how far the cursor moved since the drag began (a click moves less than kClickSlop)
};

}  // namespace facet::viewer
