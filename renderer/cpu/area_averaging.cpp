#include "cpu/area_averaging.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/error.h"
#include "shading/blending.h"
#include "shading/environment.h"
#include "scene/memory_budget.h"
#include "settings/render_settings.h"

namespace facet::cpu {
namespace {

// What the area rule keeps per binned surface, cell and fragment, priced against the frame budget.
constexpr std::uint64_t kBytesPerBinEntry = sizeof(std::uint32_t);
constexpr std::uint64_t kBytesPerCell = sizeof(AreaCell);
constexpr std::uint64_t kBytesPerFragment = 3 * sizeof(std::uint32_t) + sizeof(glm::vec4) + sizeof(std::uint8_t);

void refuseOverBudget(std::uint64_t bytes, const std::string& what) {
  if (bytes > kFrameMemoryBudget)
    throw Error("antialiasing.pattern=area: " + what + " need " + byteCount(bytes) + ", more than the frame budget of " +
                byteCount(kFrameMemoryBudget) + "; render it smaller or with grid or jittered samples");
}

// The pixels a surface's bounding box overlaps with area: [x0, x1] × [y0, y1], false for none.
bool pixelsOverlapped(const AreaSurface& s, int width, int height, int& x0, int& y0, int& x1, int& y1) {
  const double lx = std::min({s.corner[0].x, s.corner[1].x, s.corner[2].x}), hx = std::max({s.corner[0].x, s.corner[1].x, s.corner[2].x});
  const double ly = std::min({s.corner[0].y, s.corner[1].y, s.corner[2].y}), hy = std::max({s.corner[0].y, s.corner[1].y, s.corner[2].y});
  x0 = static_cast<int>(std::max(0.0, std::floor(lx)));
  y0 = static_cast<int>(std::max(0.0, std::floor(ly)));
  x1 = static_cast<int>(std::min(static_cast<double>(width), std::ceil(hx))) - 1;
  y1 = static_cast<int>(std::min(static_cast<double>(height), std::ceil(hy))) - 1;
  return x0 <= x1 && y0 <= y1;
}

}  // namespace

void AreaAveraging::collect(const SnappedTriangle& snapped, const Interpolation& planes, AreaRole role, bool additive) {
  AreaSurface s;
  // The grid puts pixel (px, py)'s centre at (256·px, 256·py): window x = X/256 + 0.5.
  for (int k = 0; k < 3; ++k) s.corner[k] = {snapped.X[k] / 256.0 + 0.5, snapped.Y[k] / 256.0 + 0.5};
  // The z-buffer's plane gives z at pixel centres (x - 0.5, y - 0.5 from pixel (0, 0)'s).
  const Plane& z = planes.depthPlane();
  s.dzdx = z.dadx;
  s.dzdy = z.dady;
  s.z0 = static_cast<double>(z.a0) - 0.5 * s.dzdx - 0.5 * s.dzdy;
  s.role = role;
  s.additive = additive;
  surfaces_.push_back(s);
}

void AreaAveraging::cut() {
  const std::size_t pixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  // Bins: each pixel's surfaces in draw order, counted first, then filled.
  std::vector<std::uint64_t> firstSurface(pixels + 1, 0);
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  std::uint64_t entries = 0;
  for (const AreaSurface& s : surfaces_)
    if (pixelsOverlapped(s, width_, height_, x0, y0, x1, y1)) {
      entries += static_cast<std::uint64_t>(x1 - x0 + 1) * static_cast<std::uint64_t>(y1 - y0 + 1);
      refuseOverBudget(entries * kBytesPerBinEntry, "the pixels' lists of " + std::to_string(surfaces_.size()) + " triangles");
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) ++firstSurface[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x) + 1];
    }
  for (std::size_t p = 0; p < pixels; ++p) firstSurface[p + 1] += firstSurface[p];
  std::vector<std::uint32_t> binned(entries);
  {
    std::vector<std::uint64_t> fill(firstSurface.begin(), firstSurface.end() - 1);
    for (std::size_t i = 0; i < surfaces_.size(); ++i)
      if (pixelsOverlapped(surfaces_[i], width_, height_, x0, y0, x1, y1))
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x)
            binned[fill[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)]++] = static_cast<std::uint32_t>(i);
  }
  // The cells, pixel by pixel, row by row from the bottom.
  pixelFirstCell_.assign(pixels + 1, 0);
  std::vector<std::uint32_t> overlapping;
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
      overlapping.assign(binned.begin() + static_cast<std::ptrdiff_t>(firstSurface[p]), binned.begin() + static_cast<std::ptrdiff_t>(firstSurface[p + 1]));
      pixelCells(surfaces_, overlapping, x, y, cells_, fragments_);
      pixelFirstCell_[p + 1] = static_cast<std::uint32_t>(cells_.size());
      for (std::size_t c = pixelFirstCell_[p]; c < cells_.size(); ++c)
        fragmentCell_.insert(fragmentCell_.end(), cells_[c].count, static_cast<std::uint32_t>(c));
    }
    refuseOverBudget(entries * kBytesPerBinEntry + cells_.size() * kBytesPerCell + fragments_.size() * kBytesPerFragment,
                     "the cells of rows 0 to " + std::to_string(y));
  }
  // Each surface's fragments, for shade(): a counting sort by surface.
  surfaceFirst_.assign(surfaces_.size() + 1, 0);
  for (const std::uint32_t s : fragments_) ++surfaceFirst_[s + 1];
  for (std::size_t s = 0; s < surfaces_.size(); ++s) surfaceFirst_[s + 1] += surfaceFirst_[s];
  bySurface_.resize(fragments_.size());
  std::vector<std::uint32_t> fill(surfaceFirst_.begin(), surfaceFirst_.end() - 1);
  for (std::size_t f = 0; f < fragments_.size(); ++f) bySurface_[fill[fragments_[f]]++] = static_cast<std::uint32_t>(f);
  shaded_.assign(fragments_.size(), glm::vec4(0.0f));
  kept_.assign(fragments_.size(), 0);
  cut_ = true;
  next_ = 0;
}

void AreaAveraging::shade(const Interpolation& planes, Shade shade) {
  if (next_ >= surfaces_.size()) throw Error("area-weighted averaging: more triangles shaded than collected");
  const std::size_t s = next_++;
  for (std::uint32_t k = surfaceFirst_[s]; k < surfaceFirst_[s + 1]; ++k) {
    const std::uint32_t f = bySurface_[k];
    const AreaCell& cell = cells_[fragmentCell_[f]];
    // The cell's pixel: its centroid lies inside the pixel's square.
    const int px = std::clamp(static_cast<int>(std::floor(cell.centroid.x)), 0, width_ - 1);
    const int py = std::clamp(static_cast<int>(std::floor(cell.centroid.y)), 0, height_ - 1);
    const auto dx = static_cast<float>(cell.centroid.x - (px + 0.5)), dy = static_cast<float>(cell.centroid.y - (py + 0.5));
    const std::optional<glm::vec4> result = shade(planes.movedBy(dx, dy), px, py);
    kept_[f] = result ? 1 : 0;
    if (result) shaded_[f] = *result;
  }
}

ColorBuffer AreaAveraging::composite(const FrameInputs& frame) const {
  ColorBuffer sum(width_, height_, glm::vec4(0.0f));
  std::vector<std::uint32_t> blended;
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
      glm::dvec4 total{0.0};
      for (std::uint32_t c = pixelFirstCell_[p]; c < pixelFirstCell_[p + 1]; ++c) {
        const AreaCell& cell = cells_[c];
        const glm::vec2 offset{static_cast<float>(cell.centroid.x - (x + 0.5)), static_cast<float>(cell.centroid.y - (y + 0.5))};
        glm::vec4 held = stored(backgroundAt(frame, x, y, offset), frame.backgroundAlpha, frame.blending);
        // The z-buffer's answer in the cell: the first kept opaque or masked surface, then the blended ones in front of it, in draw order.
        blended.clear();
        for (std::uint32_t f = cell.first; f < cell.first + cell.count; ++f) {
          if (surfaces_[fragments_[f]].role == AreaRole::Blended) {
            blended.push_back(f);
            continue;
          }
          if (!kept_[f]) continue;
          held = opaque(glm::vec3(shaded_[f]));
          break;
        }
        std::sort(blended.begin(), blended.end(), [&](std::uint32_t a, std::uint32_t b) { return fragments_[a] < fragments_[b]; });
        for (const std::uint32_t f : blended) held = blend(held, glm::vec3(shaded_[f]), shaded_[f].a, frame.blending, surfaces_[fragments_[f]].additive);
        total += cell.area * glm::dvec4(premultipliedOf(held, frame.blending));
      }
      sum.at(x, y) = glm::vec4(total);
    }
  return sum;
}

std::string AreaAveraging::summary() const {
  const std::size_t pixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  char text[160];
  std::snprintf(text, sizeof text, "area-weighted averaging: %zu cells in %zu pixels (%.2f a pixel), %zu fragments shaded, of %zu triangles",
                cells_.size(), pixels, pixels ? static_cast<double>(cells_.size()) / static_cast<double>(pixels) : 0.0, fragments_.size(),
                surfaces_.size());
  return text;
}

}  // namespace facet::cpu
