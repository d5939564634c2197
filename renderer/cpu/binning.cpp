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
  // What a triangle reads of its instance, in locals: pointers the stores below (the bins' vectors) cannot alias.
  struct Instance {
    std::size_t index, firstVertex, firstTriangle;
    const std::uint32_t* indices;
    bool cullBackFaces;
  };
  const auto instanceAt = [&](std::size_t i) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(frame.instances[i].mesh)];
    return Instance{i, vertices.firstVertex[i], vertices.firstTriangle[i], mesh.indices.data(), culling && frame.instances[i].cullBackFaces};
  };
  const std::uint8_t* const flags = vertices.flags.data();
  const auto bin = [&](const Instance& in, std::size_t global) {
    const std::size_t t = 3 * (global - in.firstTriangle);
    std::uint32_t ref[3];
    for (int k = 0; k < 3; ++k) ref[k] = static_cast<std::uint32_t>(in.firstVertex + in.indices[t + static_cast<std::size_t>(k)]);
    const std::uint8_t f0 = flags[ref[0]], f1 = flags[ref[1]], f2 = flags[ref[2]];
    if ((f0 | f1 | f2) & kNotFinite) return;

    // The triangles to draw: the triangle itself, or the clipper's fan (stored packed in `clipped`).
    std::uint32_t fan[3 * 7];
    std::size_t fanSize = 0;
    if ((f0 | f1 | f2) == 0) {
      fan[0] = ref[0], fan[1] = ref[1], fan[2] = ref[2];
      fanSize = 3;
    } else {
      if (f0 & f1 & f2) return;
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
    if (fanSize == 0) return;

    Illumination illumination[2];
    if (flat) (*flat)(static_cast<std::uint32_t>(in.index), ref, illumination);

    for (std::size_t k = 0; k < fanSize; k += 3) {
      BinnedTriangle tri;
      const float* p[3] = {bins.vertex(vertices, fan[k]), bins.vertex(vertices, fan[k + 1]), bins.vertex(vertices, fan[k + 2])};
      PixelBox box;
      if (!snapTriangle({p[0][0], p[1][0], p[2][0]}, {p[0][1], p[1][1], p[2][1]}, tri.snapped) ||
          !pixelBox(tri.snapped, 0, 0, grid.width - 1, grid.height - 1, box))
        continue;
      if (in.cullBackFaces && !tri.snapped.frontFacing) continue;  // signed area ≤ 0 is dropped
      tri.vertex[0] = fan[k], tri.vertex[1] = fan[k + 1], tri.vertex[2] = fan[k + 2];
      toSetUpOrder(tri.snapped, tri.vertex);
      tri.instance = static_cast<std::uint32_t>(in.index);
      tri.triangle = static_cast<std::uint32_t>(global);
      const auto index = static_cast<std::uint32_t>(bins.triangles.size());
      bins.triangles.push_back(tri);
      if (flat) bins.flat.insert(bins.flat.end(), {illumination[0], illumination[1]});
      for (int ty = box.minY >> kTileShift; ty <= box.maxY >> kTileShift; ++ty)
        for (int tx = box.minX >> kTileShift; tx <= box.maxX >> kTileShift; ++tx)
          bins.tiles[static_cast<std::size_t>(ty * grid.columns + tx)].push_back(index);
    }
  };
  if (order)  // an order of the frame's own (the painter's, transparency's): any instance from one triangle to the next
    for (std::size_t position = begin; position < end; ++position) bin(instanceAt(instanceOf(order[position])), order[position]);
  else  // in submission order, an instance's triangles at a time
    for (std::size_t global = begin, i = instanceOf(begin); global < end;) {
      while (global >= vertices.firstTriangle[i + 1]) ++i;
      const Instance in = instanceAt(i);
      for (const std::size_t last = std::min(end, vertices.firstTriangle[i + 1]); global < last; ++global) bin(in, global);
    }
}

}  // namespace facet::cpu
