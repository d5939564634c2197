#include "shading/fog.h"
#include "cpu/line_pass.h"
#include "shading/blending.h"

#include <algorithm>
#include <cmath>

#include "image/srgb.h"

namespace facet::cpu {
namespace {

LineVertex lineVertex(const WindowVertex& w) { return {w.x, w.y, w.z, w.invW, {w.varyings[0], w.varyings[1], w.varyings[2]}}; }

bool finite(const glm::vec4& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w); }

}  // namespace

void addSegment(const ClipVertex& a, const ClipVertex& b, const WindowVertex& windowA, const WindowVertex& windowB, const FrameInputs& frame,
                glm::vec3 baseColor, std::vector<DrawnLine>& out) {
  if (!finite(a.clip) || !finite(b.clip)) return;
  const float halfWidth = 0.5f * static_cast<float>(frame.width), halfHeight = 0.5f * static_cast<float>(frame.height);
  WindowVertex clippedA, clippedB;
  if (!clipSegment(a, b, windowA, windowB, halfWidth, halfHeight, 3, clippedA, clippedB)) return;
  DrawnLine drawn{{}, baseColor};
  if (setUpSegment(lineVertex(clippedA), lineVertex(clippedB), frame.width, frame.height, frame.lineEnds, drawn.raster)) out.push_back(drawn);
}

void addPoint(const ClipVertex& v, const WindowVertex& window, const FrameInputs& frame, glm::vec3 baseColor, std::vector<DrawnLine>& out) {
  if (!finite(v.clip) || clipMask(v.clip) != 0) return;
  DrawnLine drawn{{}, baseColor};
  if (setUpPoint(lineVertex(window), frame.width, frame.height, drawn.raster)) out.push_back(drawn);
}

void setUpLines(const Scene& scene, const FrameInputs& frame, const PassVertices& vertices, int colorVarying, std::vector<DrawnLine>& out) {
  out.clear();
  // Vertex g as the clipper sees it: clip position and its colour as varyings 0-2.
  const auto vertex = [&](std::size_t g, ClipVertex& c, WindowVertex& w) {
    const float* p = vertices.at(static_cast<std::uint32_t>(g));
    c.clip = vertices.clip[g];
    w.x = p[0], w.y = p[1], w.z = p[2], w.invW = p[3];
    for (std::size_t k = 0; k < 3; ++k) c.varyings[k] = w.varyings[k] = p[4 + static_cast<std::size_t>(colorVarying) + k];
  };
  for (std::size_t i = 0; i < frame.instances.size(); ++i) {
    const FrameInstance& instance = frame.instances[i];
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    if (mesh.lines.empty() && mesh.points.empty()) continue;
    const glm::vec3 baseColor = frame.materials[static_cast<std::size_t>(instance.material)].baseColor;
    const std::size_t first = vertices.firstVertex[i];
    ClipVertex ca, cb;
    WindowVertex wa, wb;
    for (std::size_t s = 0; s + 1 < mesh.lines.size(); s += 2) {
      vertex(first + mesh.lines[s], ca, wa);
      vertex(first + mesh.lines[s + 1], cb, wb);
      addSegment(ca, cb, wa, wb, frame, baseColor, out);
    }
    for (const std::uint32_t local : mesh.points) {
      vertex(first + local, ca, wa);
      addPoint(ca, wa, frame, baseColor, out);
    }
  }
}

void drawLines(const FrameInputs& frame, const std::vector<DrawnLine>& lines, const TileRect& r, float* depth, int depthStride, const TilePixels& color) {
  for (const DrawnLine& line : lines) {
    const PixelBox& b = line.raster.box;
    const int x0 = std::max(b.minX, r.x0), x1 = std::min(b.maxX, r.x1), y0 = std::max(b.minY, r.y0), y1 = std::min(b.maxY, r.y1);
    for (int py = y0; py <= y1; ++py)
      for (int px = x0; px <= x1; ++px) {
        if (!line.raster.covers(px, py)) continue;
        const float z = line.raster.depthAt(px, py);
        if (depth) {
          float& kept = depth[static_cast<std::size_t>(py - r.y0) * static_cast<std::size_t>(depthStride) + static_cast<std::size_t>(px - r.x0)];
          if (!(z < kept)) continue;  // LESS
          kept = z;
        }
        const glm::vec3 lit = line.baseColor * glm::vec3(line.raster.colorAt(0, px, py), line.raster.colorAt(1, px, py), line.raster.colorAt(2, px, py));
        const float d = frame.fog.mode != FogMode::None ? eyeDepth(frame, line.raster.oneOverW.at(px, py), z) : 0.0f;
        color.at(px, py) = opaque(fogged(frame.fog, lit, d));
      }
  }
}

}  // namespace facet::cpu
