#include "viewer/matrices_tab.h"

#include <algorithm>
#include <string>

#include <glm/mat4x4.hpp>
#include <imgui.h>

namespace facet::viewer {
namespace {

constexpr const char* kFaceNames[] = {"+x", "-x", "+y", "-y", "+z", "-z"};

// A 4×4 matrix as the course writes it: rows, the translation in the last column.
void drawMatrix(const char* name, const char* meaning, const glm::mat4& m) {
  ImGui::TextUnformatted(name);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", meaning);
  if (ImGui::BeginTable(name, 4, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame)) {
    for (int row = 0; row < 4; ++row) {
      ImGui::TableNextRow();
      for (int column = 0; column < 4; ++column) {
        ImGui::TableNextColumn();
        ImGui::Text("%.4f", static_cast<double>(m[column][row]));  // glm is column-major
      }
    }
    ImGui::EndTable();
  }
  ImGui::Spacing();
}

}  // namespace

void drawMatricesTab(const DrawnFrame& drawn, MatrixSelection& selection) {
  if (drawn.version == 0 || !drawn.scene) {
    ImGui::TextUnformatted("no frame yet");
    return;
  }
  const FrameInputs& frame = drawn.frame;
  if (!frame.instances.empty()) {
    selection.instance = std::clamp(selection.instance, 0, static_cast<int>(frame.instances.size()) - 1);
    const auto nameOf = [&](int i) {
      const std::string& mesh = drawn.scene->meshes[static_cast<std::size_t>(frame.instances[static_cast<std::size_t>(i)].mesh)].name;
      return std::to_string(i) + ": " + (mesh.empty() ? "mesh " + std::to_string(frame.instances[static_cast<std::size_t>(i)].mesh) : mesh);
    };
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::BeginCombo("##object", nameOf(selection.instance).c_str())) {
      for (int i = 0; i < static_cast<int>(frame.instances.size()); ++i)
        if (ImGui::Selectable(nameOf(i).c_str(), i == selection.instance)) selection.instance = i;
      ImGui::EndCombo();
    }
    const FrameInstance& instance = frame.instances[static_cast<std::size_t>(selection.instance)];
    drawMatrix("TM (the object's transformation)", "model to world: the glTF node's matrix at `time`", instance.worldFromModel);
  }
  drawMatrix("EM (the eye matrix)", "world to eye: from P_eye, P_ref and v_up", frame.eyeFromWorld);
  drawMatrix("PM (the projection matrix)", "eye to clip: perspective (theta, N, F, aspect) or parallel (W, N, F)", frame.clipFromEye);
  drawMatrix("viewport (window) matrix", "normalized device coordinates [-1,1]^2 to window pixels [0,W]x[0,H]; z kept", frame.windowFromNdc);
  if (!frame.instances.empty())
    drawMatrix("PM EM TM", "model to clip, what the vertex stage applies",
               frame.instances[static_cast<std::size_t>(selection.instance)].clipFromModel);

  ImGui::Separator();
  if (frame.lights.empty()) return;
  selection.light = std::clamp(selection.light, 0, static_cast<int>(frame.lights.size()) - 1);
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
  ImGui::SliderInt("light", &selection.light, 0, static_cast<int>(frame.lights.size()) - 1);
  const FrameLight& light = frame.lights[static_cast<std::size_t>(selection.light)];
  if (!light.hasShadowMap) {
    ImGui::TextDisabled("this light casts no shadow map (shadows.enabled, castsShadow)");
    return;
  }
  selection.face = std::clamp(selection.face, 0, light.frustum.faceCount - 1);
  if (light.frustum.faceCount > 1) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
    ImGui::SliderInt("cube face", &selection.face, 0, light.frustum.faceCount - 1, kFaceNames[selection.face]);
  }
  ImGui::Text("pass 1: N = %.4g, F = %.4g", static_cast<double>(light.frustum.near), static_cast<double>(light.frustum.far));
  const auto face = static_cast<std::size_t>(selection.face);
  drawMatrix("the light's PM EM (pass 1)", "world to the light's clip space: the shadow map's view of the scene", light.frustum.clipFromWorld[face]);
  drawMatrix("shadow matrix (pass 2)", "world to the map's (u, v, z) in [0,1]: the bias matrix times the light's PM EM", light.shadowFromWorld[face]);
}

}  // namespace facet::viewer
