#include "viewer/pixel_pick.h"

#include <cstdio>

#include "common/error.h"
#include "pipeline/triangle_coverage.h"

namespace facet::viewer {

bool PixelPick::agree(const Picked& p) { return p.glTriangle == p.cpu.triangle && p.glColor && *p.glColor == p.cpu.drawn; }

void PixelPick::pick(ViewFrame& view, int x, int y) {
  const DrawnFrame& drawn = view.drawn();
  if (drawn.version == 0 || !drawn.scene) return;
  Picked p;
  p.version = drawn.version;
  p.width = drawn.frame.width;
  p.height = drawn.frame.height;
  try {
    p.cpu = probePixel(*drawn.scene, drawn.frame, x, y);
    const std::size_t pixel = static_cast<std::size_t>(y) * static_cast<std::size_t>(drawn.frame.width) + static_cast<std::size_t>(x);
    p.glTriangle = (*view.glRenderer().render(*drawn.scene, drawn.frame, {FrameOutput::TriangleIds}).triangleIds)[pixel];
    view.invalidate();  // the triangle ids went through OpenGL's framebuffers
    const Image gl = view.glImage();
    if (!gl.empty()) p.glColor = gl.at(x, y);
    if (p.cpu.covered) {
      const SingleTriangle single = singleTriangle(*drawn.scene, drawn.frame, p.cpu.triangle);
      Renderer& cpu = view.cpuRenderer();
      const std::vector<std::uint32_t> counts = *cpu.render(single.scene, single.frame, {FrameOutput::FragmentCounts}).fragmentCounts;
      const std::vector<std::uint32_t> kept = *cpu.render(*drawn.scene, drawn.frame, {FrameOutput::TriangleIds}).triangleIds;
      p.glCoversTheSame = view.glRenderer().render(single.scene, single.frame, {FrameOutput::FragmentCounts}).fragmentCounts == counts;
      for (std::size_t i = 0; i < counts.size(); ++i) p.covered += counts[i] != 0, p.kept += counts[i] != 0 && kept[i] == p.cpu.triangle;
      p.coverage = coverageImage(counts, kept, p.cpu.triangle, drawn.frame.width, drawn.frame.height);
    }
  } catch (const Error& e) {
    p.error = e.what();
  }
  coverageTexture_->upload(p.coverage);
  picked_ = std::move(p);
  fresh_ = true;
}

void PixelPick::drawTab(std::uint64_t version) {
  if (!picked_) {
    ImGui::TextWrapped("Click a pixel of the 3D view: both backends say which triangle they kept there and what they drew, and the CPU "
                       "backend every term of the illumination equation.");
    return;
  }
  const Picked& p = *picked_;
  if (p.version != version) ImGui::TextDisabled("picked in an earlier frame: click again for this one");
  if (!p.error.empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", p.error.c_str());
    return;
  }
  if (ImGui::BeginTable("backends", 3, ImGuiTableFlags_Borders)) {
    ImGui::TableSetupColumn("pixel");
    ImGui::TableSetupColumn("OpenGL");
    ImGui::TableSetupColumn("CPU");
    ImGui::TableHeadersRow();
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("triangle");
    ImGui::TableNextColumn();
    ImGui::Text("%u", p.glTriangle);
    ImGui::TableNextColumn();
    ImGui::Text("%u", p.cpu.triangle);
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("colour");
    ImGui::TableNextColumn();
    if (p.glColor) ImGui::Text("%d %d %d", p.glColor->r, p.glColor->g, p.glColor->b);
    else ImGui::TextDisabled("not drawn");
    ImGui::TableNextColumn();
    ImGui::Text("%d %d %d", p.cpu.drawn.r, p.cpu.drawn.g, p.cpu.drawn.b);
    ImGui::EndTable();
  }
  ImGui::TextColored(agree(p) ? ImVec4(0.55f, 0.85f, 0.55f, 1.0f) : ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s",
                     agree(p) ? "the backends agree here" : "the backends differ here");
  if (p.cpu.covered) {
    ImGui::Text("coverage: %d pixel centres, %d kept; OpenGL %s", p.covered, p.kept, p.glCoversTheSame ? "covers the same" : "covers others");
    ImGui::Checkbox("show the triangle's coverage (yellow: kept, orange: hidden)", &showCoverage_);
  }
  ImGui::Separator();
  ImGui::PushTextWrapPos(0.0f);
  for (const std::string& line : describeProbe(p.cpu)) ImGui::TextUnformatted(line.c_str());
  ImGui::PopTextWrapPos();
}

void PixelPick::print() const {
  if (!picked_) return;
  if (!picked_->error.empty()) {
    std::printf("pick: %s\n", picked_->error.c_str());
    return;
  }
  const Picked& p = *picked_;
  if (p.glColor)
    std::printf("OpenGL: triangle %u, drawn %d %d %d; CPU: triangle %u, drawn %d %d %d: %s\n", p.glTriangle, p.glColor->r, p.glColor->g,
                p.glColor->b, p.cpu.triangle, p.cpu.drawn.r, p.cpu.drawn.g, p.cpu.drawn.b, agree(p) ? "the backends agree" : "the backends differ");
  if (p.cpu.covered)
    std::printf("coverage: %d pixel centres, %d kept; OpenGL %s\n", p.covered, p.kept, p.glCoversTheSame ? "covers the same" : "covers others");
  for (const std::string& line : describeProbe(picked_->cpu)) std::printf("%s\n", line.c_str());
}

void PixelPick::drawCoverage(std::uint64_t version, ImVec2 topLeft, ImVec2 bottomRight) const {
  if (!showCoverage_ || !picked_ || picked_->version != version || coverageTexture_->empty()) return;
  ImGui::GetBackgroundDrawList()->AddImage(coverageTexture_->id(), topLeft, bottomRight, kTopLeftUv, kBottomRightUv, IM_COL32(255, 255, 255, 200));
}

void PixelPick::drawMarker(std::uint64_t version, ImVec2 topLeft, ImVec2 bottomRight) const {
  if (!picked_ || picked_->version != version || picked_->width == 0) return;
  const float sx = (bottomRight.x - topLeft.x) / static_cast<float>(picked_->width);
  const float sy = (bottomRight.y - topLeft.y) / static_cast<float>(picked_->height);
  const ImVec2 c(topLeft.x + (static_cast<float>(picked_->cpu.x) + 0.5f) * sx,
                 topLeft.y + (static_cast<float>(picked_->height - 1 - picked_->cpu.y) + 0.5f) * sy);
  ImDrawList* list = ImGui::GetForegroundDrawList();
  const ImU32 color = IM_COL32(255, 230, 0, 255);
  const float r = 6.0f;
  list->AddLine(ImVec2(c.x - 2 * r, c.y), ImVec2(c.x - r * 0.5f, c.y), color, 1.5f);
  list->AddLine(ImVec2(c.x + r * 0.5f, c.y), ImVec2(c.x + 2 * r, c.y), color, 1.5f);
  list->AddLine(ImVec2(c.x, c.y - 2 * r), ImVec2(c.x, c.y - r * 0.5f), color, 1.5f);
  list->AddLine(ImVec2(c.x, c.y + r * 0.5f), ImVec2(c.x, c.y + 2 * r), color, 1.5f);
}

}  // namespace facet::viewer
