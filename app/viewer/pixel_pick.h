#pragma once
// The picked pixel: a click on the 3D view (a press and release without a
// drag) asks both backends about the pixel under it: which triangle each
// kept there and the colour each drew, side by side, and from the CPU
// backend the whole illumination equation at it (cpu/pixel_probe.h). Shown
// in the panel's Pixel tab, marked on the view.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include <imgui.h>

#include "cpu/pixel_probe.h"
#include "viewer/image_texture.h"
#include "viewer/view_frame.h"

namespace facet::viewer {

class PixelPick {
 public:
  // gl must outlive the pick.
  explicit PixelPick(const gl::GlFunctions& gl) : coverageTexture_(std::make_unique<ImageTexture>(gl)) {}
  // Probes pixel (x, y) of the frame on screen (from the bottom left, in its pixels); errors are kept for the tab.
  void pick(ViewFrame& view, int x, int y);
  // The instance the picked pixel's triangle belongs to, when one was picked.
  std::optional<int> instance() const {
    if (!picked_ || !picked_->cpu.covered) return std::nullopt;
    return picked_->cpu.instance;
  }
  // Whether a pick arrived since the last call (the panel brings its tab forward).
  bool takeFresh() { return std::exchange(fresh_, false); }
  // The Pixel tab's content.
  void drawTab(std::uint64_t version);
  // The pick on stdout, as `facet render --probe` prints it (--screenshot --pick).
  void print() const;
  // The picked triangle's coverage over the view, when the tab's box asks for it (ImGui units).
  void drawCoverage(std::uint64_t version, ImVec2 topLeft, ImVec2 bottomRight) const;
  // A cross on the view at the picked pixel; view: the 3D view's corners in ImGui units.
  void drawMarker(std::uint64_t version, ImVec2 topLeft, ImVec2 bottomRight) const;

 private:
  struct Picked {
    std::uint64_t version = 0;
    int width = 0, height = 0;           // of the frame it was picked in
    PixelProbe cpu;                      // the CPU backend's answer, with every term
    std::uint32_t glTriangle = 0;        // what OpenGL kept there (FrameOutput::TriangleIds)
    std::optional<Rgba8> glColor;        // what OpenGL drew there (none: OpenGL cannot draw the frame)
    // The picked triangle's coverage (pipeline/triangle_coverage.h): pixel centres covered and kept, by the CPU;
    // whether OpenGL covers the same ones.
    int covered = 0, kept = 0;
    bool glCoversTheSame = false;
    Image coverage;
    std::string error;
  };
  // Both backends kept the same triangle and drew the same colour.
  static bool agree(const Picked& p);

  std::optional<Picked> picked_;
  bool fresh_ = false;
  bool showCoverage_ = false;  // the tab's box: the coverage over the view
  std::unique_ptr<ImageTexture> coverageTexture_;
};

}  // namespace facet::viewer
