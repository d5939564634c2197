#include "viewer/reference_view.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>

#include <imgui.h>

namespace facet::viewer {
namespace {

const ImVec4 kErrorColor{1.0f, 0.45f, 0.4f, 1.0f};

std::string psnrText(double psnr) {
  if (std::isinf(psnr)) return "identical";
  char text[32];
  std::snprintf(text, sizeof text, "%.1f dB", psnr);
  return text;
}

// The image `size` large, its title above it; under the cursor, a tooltip
// with that pixel in both images, counted from the top left as `facet diff`
// counts.
void drawComparedImage(const char* title, const ImageTexture& texture, ImVec2 size, const ReferenceResult& result) {
  ImGui::BeginGroup();
  ImGui::TextUnformatted(title);
  ImGui::Image(texture.id(), size, kTopLeftUv, kBottomRightUv);
  const Image& gl = result.glImage;
  if (ImGui::IsItemHovered() && !gl.empty()) {
    const ImVec2 corner = ImGui::GetItemRectMin();
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const int x = std::clamp(static_cast<int>((mouse.x - corner.x) / size.x * static_cast<float>(gl.width())), 0, gl.width() - 1);
    const int fromTop = std::clamp(static_cast<int>((mouse.y - corner.y) / size.y * static_cast<float>(gl.height())), 0, gl.height() - 1);
    const int y = gl.height() - 1 - fromTop;  // Image rows run bottom first
    const Rgba8 g = gl.at(x, y), c = result.cpuImage.at(x, y);
    const auto level = [](std::uint8_t a, std::uint8_t b) { return std::abs(int(a) - int(b)); };
    ImGui::SetTooltip("pixel (%d, %d) from the top left\nOpenGL  %3d %3d %3d\nCPU     %3d %3d %3d\ndifference %d", x, fromTop, g.r, g.g,
                      g.b, c.r, c.g, c.b, std::max({level(g.r, c.r), level(g.g, c.g), level(g.b, c.b), level(g.a, c.a)}));
  }
  ImGui::EndGroup();
}

}  // namespace

ReferenceView::ReferenceView(const gl::GlFunctions& gl, int threads, bool follow, bool rayTraced)
    : worker_(threads), follow_(follow), glTexture_(gl), cpuTexture_(gl), heatTexture_(gl), rayTraced_(rayTraced) {}

void ReferenceView::update(std::uint64_t version, const std::function<ReferenceRequest()>& makeRequest) {
  if (std::optional<ReferenceResult> finished = worker_.take()) {
    if (finished->version != version) {
      note_ = "dropped a result: the frame changed while the CPU rendered it";
    } else {
      result_ = std::move(finished);
      note_.clear();
      glTexture_.upload(result_->glImage);
      cpuTexture_.upload(result_->cpuImage);
      heatTexture_.upload(result_->heatMap);
    }
  }
  const bool wanted = requested_ || (follow_ && !isCurrent(version));
  if (!wanted) return;
  if (submittedVersion_ != version) {
    ReferenceRequest request = makeRequest();
    request.rayTraced = rayTraced_;
    worker_.submit(std::move(request));
    submittedVersion_ = version;
  }
  requested_ = false;
}

void ReferenceView::drawControls(std::uint64_t version) {
  ImGui::TextWrapped("The CPU reference rasterizer, or the ray tracer, renders the frame on screen on a thread of its own; the figures compare it "
                     "with the GL image.");
  if (ImGui::Button("Render the reference")) requested_ = true;
  ImGui::Checkbox("render it after every change", &follow_);
  // The ray tracer as the reference: its exact shadow rays against the shadow maps (renderer/PIPELINE.md, "Ray tracing").
  int reference = rayTraced_ ? 1 : 0;
  const int before = reference;
  ImGui::RadioButton("the CPU rasterizer", &reference, 0);
  ImGui::SameLine();
  ImGui::RadioButton("the ray tracer", &reference, 1);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("shadow rays, reflections and refraction: the difference shows where shadow maps are wrong (acne, peter-panning, aliasing)");
  if (reference != before) {
    rayTraced_ = reference == 1;
    result_.reset();  // the image shown was the other renderer's
    submittedVersion_ = 0;
    requested_ = true;
  }

  if (worker_.busy()) ImGui::TextUnformatted(rayTraced_ ? "ray tracing..." : "rendering on the CPU...");
  if (result_ && !result_->error.empty()) ImGui::TextColored(kErrorColor, "%s", result_->error.c_str());
  if (isCurrent(version) && result_->error.empty()) {
    ImGui::Text("current: %.0f ms %s", result_->milliseconds, result_->rayTraced ? "ray tracing" : "on the CPU");
    if (result_->preview) ImGui::TextDisabled("one path a pixel so far; refining to ray.samples...");
  } else if (result_ && result_->error.empty()) {
    ImGui::TextDisabled("out of date: the frame changed since");
  }
  if (!note_.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", note_.c_str());
    ImGui::PopTextWrapPos();
  }

  if (result_ && result_->error.empty()) {
    const DiffResult& d = result_->diff;
    ImGui::Separator();
    ImGui::Text("max difference    %d of 255", d.maxDifference);
    ImGui::Text("pixels differing  %" PRId64 " (%.3f%%)", d.failingPixels, d.failingPercent);
    ImGui::Text("PSNR              %s", psnrText(d.psnr).c_str());
    if (result_->rayTraced) {
      ImGui::TextWrapped("against ray casting's exact shadows the shadow maps differ where they are wrong (acne, peter-panning, aliasing): "
                         "not a disagreement of the backends");
    } else {
      ImGui::Text("verdict           %s", std::string(kAgreementNames[static_cast<std::size_t>(agreementOf(d))]).c_str());
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("as the agreement suite judges GL against CPU (renderer/compare/backend_agreement.h):\nidentical: every byte equal; "
                          "within tolerance: none beyond the allowed difference; different: the suite would fail it");
    }
  }

  ImGui::Separator();
  ImGui::TextUnformatted("beside the panel, the window shows");
  for (std::size_t i = 0; i < kMainViewNames.size(); ++i) {
    if (ImGui::RadioButton(std::string(kMainViewNames[i]).c_str(), mainView_ == static_cast<MainView>(i))) mainView_ = static_cast<MainView>(i);
  }
  if (mainView_ != MainView::OpenGl && !isCurrent(version)) ImGui::TextDisabled("(OpenGL until the reference is current)");
  ImGui::Checkbox("images window", &showImages_);
}

void ReferenceView::drawImages(std::uint64_t version) {
  if (!showImages_ || !result_ || !result_->error.empty() || glTexture_.empty()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, 0.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(display.x * 0.5f, 0.0f), ImGuiCond_FirstUseEver);  // height 0: fit the images
  if (ImGui::Begin("Reference", &showImages_)) {
    ImGui::TextUnformatted(isCurrent(version) ? "the frame on screen" : "an earlier frame (out of date)");
    ImGui::SameLine();
    ImGui::Checkbox("heat map on the right", &imagesShowHeatMap_);
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const float width = std::max((ImGui::GetContentRegionAvail().x - spacing) * 0.5f, 1.0f);
    const ImVec2 size(width, width * static_cast<float>(glTexture_.height()) / static_cast<float>(glTexture_.width()));
    drawComparedImage("OpenGL", glTexture_, size, *result_);
    ImGui::SameLine();
    drawComparedImage(imagesShowHeatMap_ ? "difference (black: equal)" : (result_->rayTraced ? "ray tracer" : "CPU reference"),
                      imagesShowHeatMap_ ? heatTexture_ : cpuTexture_, size,
                      *result_);
  }
  ImGui::End();
}

void ReferenceView::drawMainView(std::uint64_t version, ImVec2 topLeft, ImVec2 bottomRight) const {
  if (mainView_ == MainView::OpenGl || !isCurrent(version)) return;
  const ImageTexture* texture = shownTexture(mainView_);
  if (!texture || texture->empty()) return;
  ImGui::GetBackgroundDrawList()->AddImage(texture->id(), topLeft, bottomRight, kTopLeftUv, kBottomRightUv);
}

const ImageTexture* ReferenceView::shownTexture(MainView view) const {
  switch (view) {
    case MainView::CpuReference: return &cpuTexture_;
    case MainView::Difference: return &heatTexture_;
    default: return nullptr;
  }
}

std::string ReferenceView::summary() const {
  if (!result_) return "reference: none";
  if (!result_->error.empty()) return "reference: " + result_->error;
  const DiffResult& d = result_->diff;
  char text[200];
  std::snprintf(text, sizeof text, "reference: max difference %d, %" PRId64 " pixels differ (%.3f%%), PSNR %s, %s, %s %.0f ms",
                d.maxDifference, d.failingPixels, d.failingPercent, psnrText(d.psnr).c_str(),
                result_->rayTraced ? "shadow maps against ray casting" : std::string(kAgreementNames[static_cast<std::size_t>(agreementOf(d))]).c_str(),
                result_->rayTraced ? "ray tracer" : "CPU", result_->milliseconds);
  return text;
}

}  // namespace facet::viewer
