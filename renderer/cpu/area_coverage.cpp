#include "cpu/area_coverage.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"

namespace facet::cpu {
namespace {

// Everything below works in the pixel's own frame: window coordinates minus
// (px, py), so the square is [0, 1]² and nothing cancels far from the origin.
using Polygon = std::vector<glm::dvec2>;

// A line a·x + b·y + c = 0; its positive side is where the value is > 0.
struct Line {
  double a = 0, b = 0, c = 0;
  double at(glm::dvec2 p) const { return a * p.x + b * p.y + c; }
};

// Pieces smaller than this (a fraction of the pixel) are rounding, not area.
constexpr double kNegligibleArea = 1e-12;

double signedArea(const Polygon& p) {
  double twice = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2 a = p[i], b = p[(i + 1) % p.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

// The centroid of a convex polygon, by the triangles of a fan, each at its own centroid weighted by its area.
glm::dvec2 centroidOf(const Polygon& p) {
  glm::dvec2 sum{0.0};
  double total = 0;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const double area = 0.5 * ((p[i].x - p[0].x) * (p[i + 1].y - p[0].y) - (p[i + 1].x - p[0].x) * (p[i].y - p[0].y));
    sum += area * (p[0] + p[i] + p[i + 1]) / 3.0;
    total += area;
  }
  return total != 0 ? sum / total : p[0];
}

// The part of a convex polygon on the `side` (+1 or -1) of a line (Sutherland and Hodgman), vertices on the line kept.
Polygon clipped(const Polygon& polygon, const Line& line, double side) {
  Polygon out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
    const double fp = side * line.at(p), fq = side * line.at(q);
    if (fp >= 0) out.push_back(p);
    if ((fp > 0 && fq < 0) || (fp < 0 && fq > 0)) out.push_back(p + (fp / (fp - fq)) * (q - p));
  }
  return std::abs(signedArea(out)) < kNegligibleArea ? Polygon{} : out;
}

// The three edge lines of a surface in the pixel's frame, each positive inside the triangle.
void edgeLines(const AreaSurface& s, glm::dvec2 pixel, Line (&edges)[3]) {
  glm::dvec2 p[3];
  for (int k = 0; k < 3; ++k) p[k] = s.corner[k] - pixel;
  const double orientation = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y) < 0 ? -1.0 : 1.0;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec2 from = p[i], to = p[(i + 1) % 3];
    Line& e = edges[i];
    e.a = -orientation * (to.y - from.y);
    e.b = orientation * (to.x - from.x);
    e.c = -(e.a * from.x + e.b * from.y);
  }
}

// Window z of a surface in the pixel's frame: a plane z = c + a·x + b·y.
Line depthPlane(const AreaSurface& s, glm::dvec2 pixel) {
  return {s.dzdx, s.dzdy, s.z0 + s.dzdx * pixel.x + s.dzdy * pixel.y};
}

// A cell while the pixel is being cut: its polygon and its surfaces front to back.
struct Cell {
  Polygon polygon;
  std::vector<std::uint32_t> surfaces;
};

// Whether a depth difference d changes sign inside a polygon: beyond a
// tolerance for rounding, so that coplanar surfaces do not cut each other
// along noise (their order is then the one at the centroid, ties to the
// earlier drawn, as the z-buffer's LESS).
bool crosses(const Line& d, const Polygon& polygon) {
  double low = 0, high = 0;
  for (const glm::dvec2 p : polygon) low = std::min(low, d.at(p)), high = std::max(high, d.at(p));
  const double tolerance = 1e-12 * (std::abs(d.a) + std::abs(d.b) + std::abs(d.c));
  return low < -tolerance && high > tolerance;
}

}  // namespace

void pixelCells(const std::vector<AreaSurface>& surfaces, const std::vector<std::uint32_t>& overlapping, int px, int py,
                std::vector<AreaCell>& cells, std::vector<std::uint32_t>& fragments) {
  const glm::dvec2 pixel{static_cast<double>(px), static_cast<double>(py)};
  std::vector<Cell> current{{{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}, {}}}, next;
  for (const std::uint32_t t : overlapping) {
    const AreaSurface& T = surfaces[t];
    Line edges[3];
    edgeLines(T, pixel, edges);
    const Line zT = depthPlane(T, pixel);
    next.clear();
    for (Cell& cell : current) {
      // The cell outside the triangle keeps its surfaces: the part beyond edge 0, then
      // inside 0 but beyond edge 1, then inside both but beyond edge 2.
      Polygon inside = std::move(cell.polygon);
      for (const Line& edge : edges) {
        Polygon outside = clipped(inside, edge, -1.0);
        if (!outside.empty()) next.push_back({std::move(outside), cell.surfaces});
        inside = clipped(inside, edge, 1.0);
        if (inside.empty()) break;
      }
      if (inside.empty()) continue;
      // Inside: cut where T's depth crosses a surface's, so that each part has one order.
      std::vector<Polygon> parts{std::move(inside)}, cut;
      for (const std::uint32_t s : cell.surfaces) {
        if (T.role == AreaRole::Blended && surfaces[s].role == AreaRole::Blended) continue;  // their order is the draw order
        const Line zS = depthPlane(surfaces[s], pixel);
        const Line d{zT.a - zS.a, zT.b - zS.b, zT.c - zS.c};
        cut.clear();
        for (Polygon& part : parts) {
          if (!crosses(d, part)) {
            cut.push_back(std::move(part));
            continue;
          }
          for (const double side : {1.0, -1.0}) {
            Polygon half = clipped(part, d, side);
            if (!half.empty()) cut.push_back(std::move(half));
          }
        }
        std::swap(parts, cut);
      }
      for (Polygon& part : parts) {
        // T goes before the first surface it is nearer than (T is drawn last: ties keep the earlier in front),
        // and what lies behind the first opaque surface is dropped.
        const glm::dvec2 c = centroidOf(part);
        const double depth = zT.at(c);
        std::vector<std::uint32_t> list;
        bool placed = false;
        for (const std::uint32_t s : cell.surfaces) {
          if (!placed && depth < depthPlane(surfaces[s], pixel).at(c)) {
            list.push_back(t);
            placed = true;
            if (T.role == AreaRole::Opaque) break;
          }
          list.push_back(s);
          if (surfaces[s].role == AreaRole::Opaque) break;
        }
        if (!placed && (list.empty() || surfaces[list.back()].role != AreaRole::Opaque)) list.push_back(t);
        next.push_back({std::move(part), std::move(list)});
      }
    }
    std::swap(current, next);
    if (current.size() > kMaxAreaCells)
      throw Error("antialiasing.pattern=area: pixel (" + std::to_string(px) + ", " + std::to_string(py) + ") is cut into more than " +
                  std::to_string(kMaxAreaCells) + " cells by its " + std::to_string(overlapping.size()) +
                  " triangles; render it larger or with grid or jittered samples");
  }
  for (const Cell& cell : current) {
    AreaCell out;
    out.area = std::abs(signedArea(cell.polygon));
    out.centroid = pixel + centroidOf(cell.polygon);
    out.first = static_cast<std::uint32_t>(fragments.size());
    out.count = static_cast<std::uint32_t>(cell.surfaces.size());
    fragments.insert(fragments.end(), cell.surfaces.begin(), cell.surfaces.end());
    cells.push_back(out);
  }
}

double coveredArea(const AreaSurface& surface, int px, int py) {
  const glm::dvec2 pixel{static_cast<double>(px), static_cast<double>(py)};
  Line edges[3];
  edgeLines(surface, pixel, edges);
  Polygon inside{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  for (const Line& edge : edges) {
    inside = clipped(inside, edge, 1.0);
    if (inside.empty()) return 0;
  }
  return std::abs(signedArea(inside));
}

}  // namespace facet::cpu
