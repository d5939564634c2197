#include "viewer/stage_view.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>

#include "common/error.h"
#include "compare/heat_map.h"
#include "compare/image_diff.h"

namespace facet::viewer {
namespace {

// One stage from one backend (OpenGL drawn on the window's context; the view is drawn again after).
RenderResult stageFrom(ViewFrame& view, bool gl, Stage stage) {
  const DrawnFrame& drawn = view.drawn();
  RenderResult result = renderStage(gl ? static_cast<Renderer&>(view.glRenderer()) : view.cpuRenderer(), *drawn.scene, drawn.frame, stage);
  if (gl) view.invalidate();  // the GL framebuffer held the frame on screen
  return result;
}

}  // namespace

void StageView::choose(const std::string& stage, StageSource source) {
  parseStage(stage);
  stage_ = stage;
  source_ = source;
  chosenSource_ = true;
  shownKey_.clear();
}

void StageView::update(ViewFrame& view) {
  const DrawnFrame& drawn = view.drawn();
  if (drawn.version == 0 || drawn.preview || !drawn.scene) return;
  // The image from the backend drawing the view is the view itself.
  const StageSource source = chosenSource_ ? source_ : (drawn.onCpu ? StageSource::Cpu : StageSource::OpenGl);
  const bool itself = stage_ == "image" && source == (drawn.onCpu ? StageSource::Cpu : StageSource::OpenGl);
  const std::string key = stage_ + " " + std::string(kStageSourceNames[static_cast<std::size_t>(source)]);
  if (drawn.version == version_ && key == shownKey_) return;
  version_ = drawn.version;
  shownKey_ = key;
  shown_ = Image();
  note_.clear();
  error_.clear();
  if (itself) {
    texture_.upload(shown_);
    return;
  }
  try {
    const Stage stage = parseStage(stage_);
    if (source == StageSource::Difference) {
      const RenderResult gl = stageFrom(view, true, stage), cpu = stageFrom(view, false, stage);
      const DiffResult d = compareImages(cpu.image, gl.image, backendAgreement());
      shown_ = heatMap(cpu.image, gl.image, backendAgreement());
      char text[160];
      std::snprintf(text, sizeof text, "OpenGL against the CPU: %" PRId64 " pixels differ, at most by %d: %s", d.differingPixels, d.maxDifference,
                    std::string(kAgreementNames[static_cast<std::size_t>(agreementOf(d))]).c_str());
      note_ = text;
    } else {
      RenderResult result = stageFrom(view, source == StageSource::OpenGl, stage);
      shown_ = std::move(result.image);
      if (!result.notes.empty()) note_ = result.notes.front();
    }
  } catch (const Error& e) {
    error_ = e.what();
  }
  texture_.upload(shown_);
}

void StageView::drawTab(ViewFrame& view) {
  const DrawnFrame& drawn = view.drawn();
  if (drawn.version == 0) return;
  ImGui::TextWrapped("What each stage of the pipeline made of the frame on screen, from either backend, or the heat map of where they differ.");
  const std::vector<std::string> names = stageNames(drawn.frame);
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::BeginCombo("##stage", stage_.c_str())) {
    for (const std::string& name : names)
      if (ImGui::Selectable(name.c_str(), name == stage_)) stage_ = name;
    ImGui::EndCombo();
  }
  static constexpr std::array<const char*, 3> kLabels = {"OpenGL", "CPU", "difference"};
  const StageSource current = chosenSource_ ? source_ : (drawn.onCpu ? StageSource::Cpu : StageSource::OpenGl);
  for (std::size_t i = 0; i < kLabels.size(); ++i) {
    if (i > 0) ImGui::SameLine();
    if (ImGui::RadioButton(kLabels[i], current == static_cast<StageSource>(i))) {
      source_ = static_cast<StageSource>(i);
      chosenSource_ = true;
    }
  }
  ImGui::PushTextWrapPos(0.0f);
  if (!error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", error_.c_str());
  if (!note_.empty()) ImGui::TextUnformatted(note_.c_str());
  ImGui::PopTextWrapPos();

  ImGui::Separator();
  if (ImGui::Button("Compare every stage")) compareAll(view);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("both backends draw each stage of this frame; a disagreement shows first where it starts");
  if (compared_.empty()) return;
  if (comparedVersion_ != drawn.version) ImGui::TextDisabled("(of an earlier frame)");
  if (ImGui::BeginTable("stages", 3, ImGuiTableFlags_Borders)) {
    ImGui::TableSetupColumn("stage");
    ImGui::TableSetupColumn("pixels differing");
    ImGui::TableSetupColumn("verdict");
    ImGui::TableHeadersRow();
    for (const Compared& c : compared_) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(c.stage.c_str());
      ImGui::TableNextColumn();
      if (c.error.empty()) ImGui::Text("%" PRId64, c.diff.differingPixels);
      else ImGui::TextDisabled("-");
      ImGui::TableNextColumn();
      if (!c.error.empty()) {
        ImGui::TextDisabled("not drawn");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", c.error.c_str());
      } else {
        ImGui::TextUnformatted(std::string(kAgreementNames[static_cast<std::size_t>(agreementOf(c.diff))]).c_str());
      }
    }
    ImGui::EndTable();
  }
}

void StageView::compareAll(ViewFrame& view) {
  const DrawnFrame& drawn = view.drawn();
  if (drawn.version == 0 || !drawn.scene) return;
  compared_.clear();
  comparedVersion_ = drawn.version;
  for (const std::string& name : stageNames(drawn.frame)) {
    Compared c;
    c.stage = name;
    try {
      const Stage stage = parseStage(name);
      const RenderResult gl = stageFrom(view, true, stage), cpu = stageFrom(view, false, stage);
      c.diff = compareImages(cpu.image, gl.image, backendAgreement());
    } catch (const Error& e) {
      c.error = e.what();
    }
    compared_.push_back(std::move(c));
  }
}

std::vector<std::string> StageView::comparisonLines() const {
  std::vector<std::string> lines;
  for (const Compared& c : compared_) {
    char text[256];
    if (!c.error.empty()) std::snprintf(text, sizeof text, "stage %s: not drawn: %s", c.stage.c_str(), c.error.c_str());
    else
      std::snprintf(text, sizeof text, "stage %s: %" PRId64 " pixels differ, at most by %d: %s", c.stage.c_str(), c.diff.differingPixels,
                    c.diff.maxDifference, std::string(kAgreementNames[static_cast<std::size_t>(agreementOf(c.diff))]).c_str());
    lines.emplace_back(text);
  }
  return lines;
}

void StageView::drawMainView(ImVec2 topLeft, ImVec2 bottomRight) const {
  if (shown_.empty() || texture_.empty()) return;
  // Fitted into the view with its own aspect (the shadow maps are a strip), on black.
  const float width = bottomRight.x - topLeft.x, height = bottomRight.y - topLeft.y;
  const float scale = std::min(width / static_cast<float>(shown_.width()), height / static_cast<float>(shown_.height()));
  const ImVec2 size(scale * static_cast<float>(shown_.width()), scale * static_cast<float>(shown_.height()));
  const ImVec2 corner(topLeft.x + 0.5f * (width - size.x), topLeft.y + 0.5f * (height - size.y));
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  list->AddRectFilled(topLeft, bottomRight, IM_COL32(0, 0, 0, 255));
  list->AddImage(texture_.id(), corner, ImVec2(corner.x + size.x, corner.y + size.y), kTopLeftUv, kBottomRightUv);
}

}  // namespace facet::viewer
