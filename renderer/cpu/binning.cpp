#include "cpu/binning.h"

#include <algorithm>
#include <cmath>

#include "cpu/triangle_setup.h"

namespace facet::cpu {
namespace {

void pack(const WindowVertex& w, int varyingCount, std::vector<float>& out) {
  out.insert(out.end(), {w.x, w.y, w.z, w.invW});
  out.insert(out.end(), w.varyings.begin(), w.varyings.begin() + varyingCount);
}

}  // namespace

bool snapTriangle(const float* a, const float* b, const float* c, int width, int height, BinnedTriangle& t, bool& frontFacing, int (&box)[4]) {
  constexpr float kLimit = 1 << 22;
  for (const float* v : {a, b, c})
    if (!(std::fabs(v[0]) < kLimit && std::fabs(v[1]) < kLimit)) return false;
  std::int64_t X[3] = {snapToGrid(a[0]), snapToGrid(b[0]), snapToGrid(c[0])};
  std::int64_t Y[3] = {snapToGrid(a[1]), snapToGrid(b[1]), snapToGrid(c[1])};
  const std::int64_t area = (X[0] - X[1]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[0] - Y[1]);
  if (area == 0) return false;
  frontFacing = area < 0;
  if (area < 0) {
    std::swap(X[0], X[1]);
    std::swap(Y[0], Y[1]);
  }
  for (int i = 0; i < 3; ++i) {
    t.X[i] = static_cast<std::int32_t>(X[i]);
    t.Y[i] = static_cast<std::int32_t>(Y[i]);
  }
  const std::int64_t minX = std::min({X[0], X[1], X[2]}), maxX = std::max({X[0], X[1], X[2]});
  const std::int64_t minY = std::min({Y[0], Y[1], Y[2]}), maxY = std::max({Y[0], Y[1], Y[2]});
  box[0] = static_cast<int>(std::max<std::int64_t>(0, (minX + 255) >> 8));
  box[1] = static_cast<int>(std::max<std::int64_t>(0, (minY + 255) >> 8));
  box[2] = static_cast<int>(std::min<std::int64_t>(width - 1, maxX >> 8));
  box[3] = static_cast<int>(std::min<std::int64_t>(height - 1, maxY >> 8));
  return box[0] <= box[2] && box[1] <= box[3];
}

void binTriangles(const Scene& scene, const FrameInputs& frame, const PassVertices& vertices, const TileGrid& grid, bool cullBackFaces,
                  std::size_t begin, std::size_t end, WorkerBins& bins, const FlatIllumination* flat) {
  bins.triangles.clear();
  bins.clipped.clear();
  bins.flat.clear();
  if (bins.tiles.size() < static_cast<std::size_t>(grid.count())) bins.tiles.resize(static_cast<std::size_t>(grid.count()));
  for (std::size_t t = 0; t < static_cast<std::size_t>(grid.count()); ++t) bins.tiles[t].clear();
  const int varyingCount = vertices.stride - 4;
  const float halfWidth = 0.5f * static_cast<float>(grid.width), halfHeight = 0.5f * static_cast<float>(grid.height);

  std::size_t instance = static_cast<std::size_t>(std::upper_bound(vertices.firstTriangle.begin(), vertices.firstTriangle.end(), begin) -
                                                  vertices.firstTriangle.begin()) - 1;
  for (std::size_t global = begin; global < end; ++global) {
    while (global >= vertices.firstTriangle[instance + 1]) ++instance;
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(frame.instances[instance].mesh)];
    const std::size_t first = vertices.firstVertex[instance];
    const std::size_t t = 3 * (global - vertices.firstTriangle[instance]);
    const std::uint32_t local[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    std::uint32_t ref[3];
    for (int k = 0; k < 3; ++k) ref[k] = static_cast<std::uint32_t>(first + local[k]);
    const std::uint8_t f0 = vertices.flags[ref[0]], f1 = vertices.flags[ref[1]], f2 = vertices.flags[ref[2]];
    if ((f0 | f1 | f2) & kNotFinite) continue;

    // The triangles to draw: the triangle itself, or the clipper's fan (stored packed in `clipped`).
    std::uint32_t fan[3 * 7];
    std::size_t fanSize = 0;
    if ((f0 | f1 | f2) == 0) {
      fan[0] = ref[0], fan[1] = ref[1], fan[2] = ref[2];
      fanSize = 3;
    } else {
      if (f0 & f1 & f2) continue;
      ClipVertex c[3];
      WindowVertex w[3];
      for (int k = 0; k < 3; ++k) {
        const float* p = vertices.at(ref[k]);
        c[k].clip = vertices.clip[ref[k]];
        w[k].x = p[0], w[k].y = p[1], w[k].z = p[2], w[k].invW = p[3];
        std::copy(p + 4, p + 4 + varyingCount, c[k].varyings.begin());
        std::copy(p + 4, p + 4 + varyingCount, w[k].varyings.begin());
      }
      bins.scratch.clear();
      clipTriangle(c[0], c[1], c[2], w[0], w[1], w[2], halfWidth, halfHeight, varyingCount, bins.scratch);
      for (const WindowVertex& v : bins.scratch) {
        fan[fanSize++] = kClippedVertex | static_cast<std::uint32_t>(bins.clipped.size() / static_cast<std::size_t>(vertices.stride));
        pack(v, varyingCount, bins.clipped);
      }
    }
    if (fanSize == 0) continue;

    Illumination illumination[2];
    if (flat) (*flat)(static_cast<std::uint32_t>(instance), ref, illumination);

    for (std::size_t k = 0; k < fanSize; k += 3) {
      BinnedTriangle tri;
      bool front = true;
      int box[4];
      if (!snapTriangle(bins.vertex(vertices, fan[k]), bins.vertex(vertices, fan[k + 1]), bins.vertex(vertices, fan[k + 2]), grid.width, grid.height,
                tri, front, box))
        continue;
      if (cullBackFaces && !front) continue;  // signed area ≤ 0 is dropped
      tri.vertex[0] = fan[k], tri.vertex[1] = fan[k + 1], tri.vertex[2] = fan[k + 2];
      tri.instance = static_cast<std::uint32_t>(instance) | (front ? 0u : kBackFacing);
      const auto index = static_cast<std::uint32_t>(bins.triangles.size());
      bins.triangles.push_back(tri);
      if (flat) bins.flat.insert(bins.flat.end(), {illumination[0], illumination[1]});
      for (int ty = box[1] >> kTileShift; ty <= box[3] >> kTileShift; ++ty)
        for (int tx = box[0] >> kTileShift; tx <= box[2] >> kTileShift; ++tx)
          bins.tiles[static_cast<std::size_t>(ty * grid.columns + tx)].push_back(index);
    }
  }
}

}  // namespace facet::cpu
