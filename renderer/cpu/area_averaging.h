#pragma once
// The course's area-weighted averaging as a frame (renderer/PIPELINE.md,
// "Area-weighted averaging"): the lit pass's triangles are
// collected as surfaces, every pixel is cut into cells (cpu/area_coverage.h),
// the same triangles are drawn again to shade each cell's surfaces at the
// cell's centroid, and each pixel sums its cells weighted by their areas.
// The CPU backend draws `antialiasing.pattern=area` frames with it
// (area_averaged_frame.h).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "cpu/area_coverage.h"
#include "common/function_ref.h"
#include "cpu/interpolation.h"
#include "cpu/triangle_setup.h"
#include "image/color_buffer.h"
#include "pipeline/frame_inputs.h"

namespace facet::cpu {

class AreaAveraging {
 public:
  AreaAveraging(int width, int height) : width_(width), height_(height) {}

  // Until cut(): the lit pass's triangles, as set up, in draw order.
  bool collecting() const { return !cut_; }
  void collect(const SnappedTriangle& snapped, const Interpolation& planes, AreaRole role, bool additive);

  // Every pixel's cells. Throws facet::Error past kMaxAreaCells in a pixel,
  // or when the cells would pass the frame budget.
  void cut();

  // After cut(): the same triangles again, in the same order; `shade` gives
  // the linear colour and α of the triangle's fragment at a cell of pixel
  // (px, py) from the planes moved to the cell's centroid, or nothing where
  // a mask discards it.
  using Shade = FunctionRef<std::optional<glm::vec4>(const Interpolation& moved, int px, int py)>;
  void shade(const Interpolation& planes, Shade shade);

  // Each pixel: the sum of its cells' colours, premultiplied (C·α, α),
  // weighted by their areas (summing to 1), for the resolve.
  ColorBuffer composite(const FrameInputs& frame) const;

  // "N cells in M pixels, K fragments shaded": what the frame cost.
  std::string summary() const;

 private:
  int width_, height_;
  bool cut_ = false;
  std::vector<AreaSurface> surfaces_;
  std::vector<AreaCell> cells_;
  std::vector<std::uint32_t> pixelFirstCell_;  // cells [pixelFirstCell_[p], pixelFirstCell_[p + 1]) of pixel p
  std::vector<std::uint32_t> fragments_;       // each cell's surfaces, front to back
  std::vector<std::uint32_t> fragmentCell_;    // the cell of each fragment
  std::vector<std::uint32_t> surfaceFirst_, bySurface_;  // fragments of surface s: bySurface_[surfaceFirst_[s] ..]
  std::vector<glm::vec4> shaded_;              // each fragment's colour and α
  std::vector<std::uint8_t> kept_;             // 0 where a mask discarded it
  std::size_t next_ = 0;                       // shade(): the surface being drawn
};

}  // namespace facet::cpu
