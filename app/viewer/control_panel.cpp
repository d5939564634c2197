#include "viewer/control_panel.h"

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <utility>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "viewer/settings_panel.h"

namespace facet::viewer {
namespace {

const ImVec4 kErrorColor{1.0f, 0.45f, 0.4f, 1.0f};
const ImVec4 kDoneColor{0.55f, 0.85f, 0.55f, 1.0f};
// Below this width (ImGui units) "parallelWidth" and a drag box no longer
// fit side by side; the 3D view keeps at least kViewMinWidth.
constexpr float kPanelMinWidth = 280.0f, kViewMinWidth = 64.0f;

void helpMarker(const char* text) {
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

void drawStatus(ViewerState& state, const FrameStats& stats, bool& redrawEveryFrame) {
  ImGui::TextUnformatted(state.scene->source.c_str());
  ImGui::Text("%zu triangles, %d light%s, %d shadow map%s", stats.triangles, stats.lights, stats.lights == 1 ? "" : "s", stats.shadowMaps,
              stats.shadowMaps == 1 ? "" : "s");
  ImGui::Text("3D frame %.1f ms, window frame %.1f ms", stats.drawMilliseconds, stats.windowMilliseconds);
  helpMarker("medians of the last 60 frames\n3D frame: the backend's passes (shadow, lit, resolve)\nwindow frame: UI, the 3D frame when it changed, the swap");
  ImGui::TextUnformatted("draw with");
  for (std::size_t i = 0; i < kFrameBackendNames.size(); ++i) {
    ImGui::SameLine();
    static constexpr std::array<const char*, 3> kLabels = {"auto", "OpenGL", "CPU"};
    if (ImGui::RadioButton(kLabels[i], state.backend == static_cast<FrameBackend>(i))) state.backend = static_cast<FrameBackend>(i);
  }
  helpMarker("auto: the CPU rasterizer where OpenGL is a software rasterizer (llvmpipe), which it outruns; else OpenGL.\n"
             "Both draw the same bytes: the agreement suite holds them to it.");
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
  ImGui::SliderInt("drag preview (1/N of each side)", &state.dragPreview, 1, kMaxDragPreview);
  helpMarker("while a drag or the wheel moves the camera, frames are drawn at 1/N of the view's width and height and scaled up;\n"
             "the frame at full size follows when the camera stops. 1: always full size");
  ImGui::Checkbox("redraw every frame", &redrawEveryFrame);
  helpMarker("draw the 3D frame every window frame, not only after a change, to time it");
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("%s", stats.backend.c_str());
  ImGui::TextDisabled("%s", stats.renderer.c_str());
  if (!stats.drawError.empty()) ImGui::TextColored(kErrorColor, "cannot draw these settings: %s", stats.drawError.c_str());
  if (!state.message.empty()) ImGui::TextColored(state.messageIsError ? kErrorColor : kDoneColor, "%s", state.message.c_str());
  ImGui::PopTextWrapPos();
}

// A text field the width of the tab, with its buttons on the line below.
void pathField(const char* id, std::string& path) {
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputText(id, &path);
}

void drawFilesTab(ViewerState& state, PanelRequests& requests) {
  ImGui::TextUnformatted("animation: glTF node animations and particles at time");
  ImGui::Checkbox("play (space)", &state.playing);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderFloat("##time", &state.settings.time, 0.0f, 30.0f, "%.2f s");
  ImGui::Separator();
  ImGui::TextUnformatted("scene: a .gltf or .glb file, or builtin:NAME");
  pathField("##scene", state.scenePath);
  if (ImGui::Button("Open scene")) loadSceneFile(state, state.scenePath);
  helpMarker("opens with the scene's own camera and lights where the settings leave them auto");
  ImGui::SameLine();
  ImGui::TextDisabled("or drop a file on the window");

  if (!state.recentFiles.empty()) {
    ImGui::TextUnformatted("recent:");
    for (const std::string& path : state.recentFiles) {
      if (ImGui::SmallButton(path.c_str())) {
        openDroppedFile(state, path);
        break;  // the list changed under the loop
      }
    }
  }

  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextUnformatted("settings: JSON, as facet render --settings reads it");
  pathField("##settings", state.settingsPath);
  if (ImGui::Button("Save settings")) saveSettings(state);
  ImGui::SameLine();
  if (ImGui::Button("Load settings")) loadSettings(state);

  ImGui::Spacing();
  ImGui::Separator();
  ImGui::TextUnformatted("screenshot: PNG of the 3D view, without the panel");
  ImGui::PushID("screenshot");
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputTextWithHint("##path", "empty: facet-view-N.png", &state.screenshotPath);
  ImGui::PopID();
  if (ImGui::Button("Save screenshot (F12)")) requests.screenshot = true;
}

void drawHelpTab() {
  static constexpr std::array<std::array<const char*, 2>, 15> kKeys = {{
      {"left drag", "orbit around the reference point"},
      {"right or middle drag", "pan"},
      {"wheel", "zoom"},
      {"1  2  3", "flat, Gouraud, Phong shading"},
      {"C", "back-face culling on / off"},
      {"S", "shadows on / off"},
      {"P", "perspective / parallel"},
      {"R", "reset the camera"},
      {"F12, Ctrl+S", "screenshot of the 3D view"},
      {"H", "hide / show the panel"},
      {"space", "play / pause the animation (glTF node animations, particles)"},
      {"Esc", "quit"},
      {"drop a file", "open a .gltf or .glb scene, or a .json settings file"},
      {"ctrl+click", "type a value into a slider"},
      {"click the view", "the pixel in both backends, and the illumination equation's terms (Pixel tab)"},
  }};
  ImGui::TextWrapped("The first mouse move of an auto camera makes it manual, starting where auto put it. R brings back the camera of the command line (or of the settings file loaded last).");
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
    for (const auto& [key, what] : kKeys) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(key);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(what);
    }
    ImGui::EndTable();
  }
}

// A tab whose content scrolls under the status lines, which stay.
template <class Fn>
void tab(const char* name, Fn&& drawContent, bool select) {
  if (!ImGui::BeginTabItem(name, nullptr, select ? ImGuiTabItemFlags_SetSelected : 0)) return;
  ImGui::BeginChild(name);
  drawContent();
  ImGui::EndChild();
  ImGui::EndTabItem();
}

}  // namespace

PanelRequests drawControlPanel(ViewerState& state, const FrameStats& stats, ReferenceView& reference, PixelPick& pick, ViewFrame& view,
                               StageView& stages, MatrixSelection& matrices, bool& redrawEveryFrame, float& width) {
  PanelRequests requests;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // Docked: the left edge, the whole height; only its right edge moves, and the 3D view takes the rest.
  const float widest = std::max(kPanelMinWidth, display.x - kViewMinWidth);
  ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(std::clamp(width, kPanelMinWidth, widest), display.y), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(kPanelMinWidth, display.y), ImVec2(widest, display.y));
  const bool open = ImGui::Begin("facet", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBringToFrontOnFocus);
  width = ImGui::GetWindowWidth();
  if (open) {
    drawStatus(state, stats, redrawEveryFrame);
    if (ImGui::BeginTabBar("tabs")) {
      // --tab: brought forward once, by its name in lower case.
      const std::string asked = std::exchange(state.openTab, {});
      const auto opens = [&](std::string_view name) { return asked == name; };
      tab("Settings", [&] { drawSettingsPanel(state.settings, *state.scene, state.sphere); }, opens("settings"));
      tab("Files", [&] { drawFilesTab(state, requests); }, opens("files"));
      tab("Reference", [&] { reference.drawControls(stats.version); }, opens("reference"));
      const bool picked = pick.takeFresh();
      if (picked && pick.instance()) matrices.instance = *pick.instance();  // the picked triangle's object
      tab("Pixel", [&] { pick.drawTab(stats.version); }, picked || opens("pixel"));
      tab("Stages", [&] { stages.drawTab(view); }, opens("stages"));
      tab("Matrices", [&] { drawMatricesTab(view.drawn(), matrices); }, opens("matrices"));
      tab("Help", [] { drawHelpTab(); }, opens("help"));
      ImGui::EndTabBar();
    }
  }
  ImGui::End();
  return requests;
}

}  // namespace facet::viewer
