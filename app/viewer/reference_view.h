#pragma once
// The reference view: the CPU rasterizer's image of the frame on screen,
// beside the GL image or as a difference heat map, with compareImages'
// figures. Rendered on demand or after every change by ReferenceWorker; the
// window keeps drawing meanwhile.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "viewer/image_texture.h"
#include "viewer/reference_worker.h"

namespace facet::viewer {

// What fills the window behind the panel.
enum class MainView { OpenGl, CpuReference, Difference, Count };
inline constexpr std::array<std::string_view, static_cast<std::size_t>(MainView::Count)> kMainViewNames = {"OpenGL", "CPU reference",
                                                                                                          "difference"};

class ReferenceView {
 public:
  // gl must outlive the view. threads: the CPU renderer's (0: one per core).
  ReferenceView(const gl::GlFunctions& gl, int threads, bool follow, bool rayTraced = false);

  // Once a frame. version: the frame on screen (what GlFrameRenderer's
  // framebuffer holds). Takes a finished result, dropping it when the frame
  // changed while it rendered, and submits makeRequest() when asked to, or
  // when following changes and the shown result is not of this version.
  void update(std::uint64_t version, const std::function<ReferenceRequest()>& makeRequest);

  // The panel's tab: buttons, state, figures.
  void drawControls(std::uint64_t version);
  // A window of its own: the GL and CPU images (or the heat map) side by side.
  void drawImages(std::uint64_t version);
  // The CPU image or the heat map over the 3D view (from topLeft to
  // bottomRight, ImGui units), when chosen and current.
  void drawMainView(std::uint64_t version, ImVec2 topLeft, ImVec2 bottomRight) const;

  // A result (or an error) for this version is in: what --screenshot waits for.
  bool isCurrent(std::uint64_t version) const { return result_ && result_->version == version; }
  // And not the ray tracer's one-path preview: the figures are the frame's.
  bool isFinal(std::uint64_t version) const { return isCurrent(version) && !result_->preview; }
  bool busy() const { return worker_.busy(); }
  // One line of figures ("max difference 1, ..."), or the error.
  std::string summary() const;

 private:
  const ImageTexture* shownTexture(MainView view) const;

  ReferenceWorker worker_;
  bool follow_;
  bool requested_ = false;                 // the button asked for one render
  std::uint64_t submittedVersion_ = 0;     // versions start at 1
  std::optional<ReferenceResult> result_;  // the last result of the frame on screen, or an older one
  std::string note_;                       // why a result was dropped
  ImageTexture glTexture_, cpuTexture_, heatTexture_;
  MainView mainView_ = MainView::OpenGl;
  bool showImages_ = true;
  bool imagesShowHeatMap_ = false;         // the images window's right image
  bool rayTraced_ = false;                 // compare with the ray tracer, not the CPU rasterizer
};

}  // namespace facet::viewer
