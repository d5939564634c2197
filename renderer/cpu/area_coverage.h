#pragma once
// The course's area-weighted averaging, its geometry (renderer/PIPELINE.md,
// "Area-weighted averaging"): a pixel's square cut into convex
// cells over which the same surfaces lie in the same depth order, so that
// each visible part of each polygon is known with its exact area.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "vocabulary/limits.h"

namespace facet::cpu {

// How a surface takes part in visibility: an opaque one hides what lies
// behind it; a masked one only where its mask keeps the fragment (known
// when it is shaded); a blended one hides nothing and blends in draw order.
enum class AreaRole : std::uint8_t { Opaque, Masked, Blended };

// A triangle as the area rule sees it, in window coordinates (pixels; pixel
// (px, py) is the square [px, px + 1] × [py, py + 1]).
struct AreaSurface {
  glm::dvec2 corner[3];          // the snapped corners, either winding
  double z0 = 0, dzdx = 0, dzdy = 0;  // window z = z0 + dzdx·x + dzdy·y
  AreaRole role = AreaRole::Opaque;
  bool additive = false;         // blended by the additive equation
};

// A convex part of one pixel: its area (a fraction of the pixel), its
// centroid (window coordinates), and its surfaces front to back, cut after
// the first opaque one: `count` indices from `first` in the fragment list.
struct AreaCell {
  double area = 0;
  glm::dvec2 centroid{0.0};
  std::uint32_t first = 0, count = 0;
};

// Cuts pixel (px, py) by the surfaces `overlapping` it (indices into
// `surfaces`, in draw order; each index is also its draw order) and appends
// the pixel's cells to `cells` and their surface lists to `fragments`.
// Throws facet::Error naming the pixel past kMaxAreaCells.
void pixelCells(const std::vector<AreaSurface>& surfaces, const std::vector<std::uint32_t>& overlapping, int px, int py,
                std::vector<AreaCell>& cells, std::vector<std::uint32_t>& fragments);

// Area of the convex polygon's intersection with pixel (px, py)'s square, for
// tests: the sum of a lone surface's cells there.
double coveredArea(const AreaSurface& surface, int px, int py);

}  // namespace facet::cpu
