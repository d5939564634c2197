#pragma once
// The stages of the frame on screen (render/stage.h): the image, overdraw,
// depth, shadow maps, normals, each light's contribution, from OpenGL or
// the CPU backend or as the heat map of their difference, shown over the 3D
// view; and every stage compared between the backends at once, so that a
// disagreement is traced to the stage where it starts. The panel's Stages
// tab; `facet view --stage NAME --stage-source gl|cpu|difference`.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <imgui.h>

#include "compare/backend_agreement.h"
#include "render/stage.h"
#include "viewer/image_texture.h"
#include "viewer/view_frame.h"

namespace facet::viewer {

enum class StageSource { OpenGl, Cpu, Difference, Count };
inline constexpr std::array<std::string_view, static_cast<std::size_t>(StageSource::Count)> kStageSourceNames = {"gl", "cpu", "difference"};

class StageView {
 public:
  // gl must outlive the view.
  explicit StageView(const gl::GlFunctions& gl) : texture_(gl) {}

  // Chooses what is shown (a stage name as render/stage.h reads it); throws facet::UsageError for a name it does not read.
  void choose(const std::string& stage, StageSource source);

  // Once a frame: draws the chosen stage of the frame on screen when it, the
  // stage or the source changed. The window then shows it over the 3D view.
  void update(ViewFrame& view);
  // The Stages tab.
  void drawTab(ViewFrame& view);
  // The stage over the 3D view (ImGui units), unless the chosen one is the image from the backend drawing the view.
  void drawMainView(ImVec2 topLeft, ImVec2 bottomRight) const;

  // What the view shows in place of the frame: an empty image when it shows the frame itself.
  const Image& shownImage() const { return shown_; }
  // The comparison of every stage, after compareAll: one line each.
  std::vector<std::string> comparisonLines() const;
  // Renders every stage the frame can show with both backends and compares them (agreement thresholds).
  void compareAll(ViewFrame& view);

 private:
  struct Compared {
    std::string stage;
    DiffResult diff;
    std::string error;  // a backend that does not draw it
  };

  std::string stage_ = "image";
  StageSource source_ = StageSource::OpenGl;
  bool chosenSource_ = false;   // the source was chosen (else: the backend drawing the view)
  std::uint64_t version_ = 0;   // of the frame shown_ was drawn for
  std::string shownKey_;        // stage and source of shown_
  Image shown_;
  std::string note_, error_;    // the stage's figures, or why it cannot be drawn
  ImageTexture texture_;
  std::uint64_t comparedVersion_ = 0;
  std::vector<Compared> compared_;
};

}  // namespace facet::viewer
