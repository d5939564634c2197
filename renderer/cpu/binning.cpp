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

void binTriangles(const Scene& scene, const FrameInputs& frame, const PassVertices& vertices, const TileGrid& grid, bool culling,
                  std::size_t begin, std::size_t end, WorkerBins& bins, const FlatIllumination* flat, const std::uint32_t* order) {
  bins.triangles.clear();
  bins.clipped.clear();
  bins.flat.clear();
  if (bins.tiles.size() < static_cast<std::size_t>(grid.count())) bins.tiles.resize(static_cast<std::size_t>(grid.count()));
  for (std::size_t t = 0; t < static_cast<std::size_t>(grid.count()); ++t) bins.tiles[t].clear();
  const int varyingCount = vertices.stride - 4;
  const float halfWidth = 0.5f * static_cast<float>(grid.width), halfHeight = 0.5f * static_cast<float>(grid.height);

  const auto instanceOf = [&](std::size_t global) {
    return static_cast<std::size_t>(std::upper_bound(vertices.firstTriangle.begin(), vertices.firstTriangle.end(), global) -
                                    vertices.firstTriangle.begin()) - 1;
  };
  std::size_t instance = order ? 0 : instanceOf(begin);
  for (std::size_t position = begin; position < end; ++position) {
    const std::size_t global = order ? order[position] : position;
    if (order) instance = instanceOf(global);
    else while (global >= vertices.firstTriangle[instance + 1]) ++instance;
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(frame.instances[instance].mesh)];
    const bool cullBackFaces = culling && frame.instances[instance].cullBackFaces;
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
      const float* p[3] = {bins.vertex(vertices, fan[k]), bins.vertex(vertices, fan[k + 1]), bins.vertex(vertices, fan[k + 2])};
      PixelBox box;
      if (!snapTriangle({p[0][0], p[1][0], p[2][0]}, {p[0][1], p[1][1], p[2][1]}, tri.snapped) ||
          !pixelBox(tri.snapped, 0, 0, grid.width - 1, grid.height - 1, box))
        continue;
      if (cullBackFaces && !tri.snapped.frontFacing) continue;  // signed area ≤ 0 is dropped
      tri.vertex[0] = fan[k], tri.vertex[1] = fan[k + 1], tri.vertex[2] = fan[k + 2];
      toSetUpOrder(tri.snapped, tri.vertex);
      tri.instance = static_cast<std::uint32_t>(instance);
      tri.triangle = static_cast<std::uint32_t>(global);
      const auto index = static_cast<std::uint32_t>(bins.triangles.size());
      bins.triangles.push_back(tri);
      if (flat) bins.flat.insert(bins.flat.end(), {illumination[0], illumination[1]});
      for (int ty = box.minY >> kTileShift; ty <= box.maxY >> kTileShift; ++ty)
        for (int tx = box.minX >> kTileShift; tx <= box.maxX >> kTileShift; ++tx)
          bins.tiles[static_cast<std::size_t>(ty * grid.columns + tx)].push_back(index);
    }
  }
}

}  // namespace facet::cpu
