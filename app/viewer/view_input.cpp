#include "viewer/view_input.h"

#include <algorithm>
#include <cmath>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "viewer/camera_controls.h"

namespace facet::viewer {
namespace {

// The camera a mouse move edits: auto becomes manual where auto put it, so
// the first drag starts from the picture on screen.
CameraSettings& manualCamera(ViewerState& state) {
  if (state.settings.camera.source == Source::Auto) state.settings = materialize(*state.scene, state.settings, true, false);
  return state.settings.camera;
}

}  // namespace

ViewRequests ViewInput::update(ViewerState& state, const std::vector<KeyPress>& keys, float viewLeft) {
  const ImGuiIO& io = ImGui::GetIO();
  RenderSettings& settings = state.settings;
  ViewRequests requests;
  const float viewWidth = std::max(1.0f, io.DisplaySize.x - viewLeft);

  // A drag belongs to the view when it starts outside every ImGui window,
  // even if the cursor then crosses the panel.
  if (dragButton_ < 0 && !io.WantCaptureMouse) {
    for (int button : {ImGuiMouseButton_Left, ImGuiMouseButton_Right, ImGuiMouseButton_Middle})
      if (ImGui::IsMouseClicked(button)) dragButton_ = button, dragDistance_ = 0;
  }
  if (dragButton_ >= 0) dragDistance_ += std::abs(io.MouseDelta.x) + std::abs(io.MouseDelta.y);
  if (dragButton_ >= 0 && !ImGui::IsMouseDown(dragButton_)) {
    // A left click that did not drag picks the pixel under it (the camera moved by less than the slop is kept).
    constexpr float kClickSlop = 3.0f;
    if (dragButton_ == ImGuiMouseButton_Left && dragDistance_ < kClickSlop && io.MousePos.x >= viewLeft) {
      requests.picked = true;
      requests.pickX = io.MousePos.x;
      requests.pickY = io.MousePos.y;
    }
    dragButton_ = -1;
  }
  if (dragButton_ >= 0 && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
    CameraSettings& camera = manualCamera(state);
    const CameraSettings before = camera;
    if (dragButton_ == ImGuiMouseButton_Left)
      orbit(camera, {io.MouseDelta.x, io.MouseDelta.y}, io.DisplaySize.y);
    else
      pan(camera, {io.MouseDelta.x, io.MouseDelta.y}, viewWidth);
    moveDepthRange(camera, before, state.sphere);
    requests.cameraMoved = true;
  }
  if (!io.WantCaptureMouse && io.MouseWheel != 0.0f) {
    CameraSettings& camera = manualCamera(state);
    const CameraSettings before = camera;
    zoom(camera, io.MouseWheel, 1e-3f * state.sphere.radius);
    moveDepthRange(camera, before, state.sphere);
    requests.cameraMoved = true;
  }

  if (io.WantCaptureKeyboard) return requests;  // typing into a text field
  for (const KeyPress& press : keys) {
    const bool ctrl = (press.mods & GLFW_MOD_CONTROL) != 0;
    switch (press.key) {
      case GLFW_KEY_1: settings.shading = ShadingMode::Flat; break;
      case GLFW_KEY_2: settings.shading = ShadingMode::Gouraud; break;
      case GLFW_KEY_3: settings.shading = ShadingMode::Phong; break;
      case GLFW_KEY_4: settings.shading = ShadingMode::Pbr; break;
      case GLFW_KEY_C: settings.cullBackFaces = !settings.cullBackFaces; break;
      case GLFW_KEY_S:
        if (ctrl) requests.screenshot = true;
        else settings.shadows.enabled = !settings.shadows.enabled;
        break;
      case GLFW_KEY_P:
        if (settings.camera.source == Source::Auto)  // auto fits either projection itself
          settings.camera.projection =
              settings.camera.projection == ProjectionKind::Perspective ? ProjectionKind::Parallel : ProjectionKind::Perspective;
        else
          toggleProjection(settings.camera, state.sphere);
        break;
      case GLFW_KEY_R: settings.camera = state.startSettings.camera; break;
      case GLFW_KEY_F12: requests.screenshot = true; break;
      case GLFW_KEY_SPACE: state.playing = !state.playing; break;
      case GLFW_KEY_H: requests.togglePanel = !requests.togglePanel; break;
      case GLFW_KEY_ESCAPE: requests.quit = true; break;
      default: break;
    }
  }
  return requests;
}

}  // namespace facet::viewer
