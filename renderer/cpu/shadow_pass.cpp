// Pass 1 of the course's 2-pass shadow algorithm: a depth-only z-buffer pass
// from the light into an S×S float map, one per face.
#include <algorithm>
#include <atomic>

#include "cpu/binning.h"
#include "cpu/interpolation.h"
#include "cpu/passes.h"
#include "cpu/tile_raster.h"
#include "cpu/vertex_math.h"

namespace facet::cpu {

void forEachRange(ThreadPool& pool, std::size_t n, FunctionRef<void(std::size_t, std::size_t, int)> work) {
  const auto workers = static_cast<std::size_t>(pool.size());
  pool.run([&](int w) {
    const auto i = static_cast<std::size_t>(w);
    const std::size_t begin = n * i / workers, end = n * (i + 1) / workers;
    work(begin, end, w);  // an empty range too: phase 2 clears the worker's bins
  });
}

void prepareFrame(ThreadPool& pool, FrameBuffers& buffers, const Scene& scene, const FrameInputs& frame) {
  PassVertices& v = buffers.vertices;
  v.firstVertex.clear();
  v.firstTriangle.clear();
  std::size_t vertices = 0, triangles = 0;
  for (const FrameInstance& instance : frame.instances) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    v.firstVertex.push_back(vertices);
    v.firstTriangle.push_back(triangles);
    vertices += mesh.positions.size();
    triangles += mesh.indices.size() / 3;
  }
  v.firstVertex.push_back(vertices);
  v.firstTriangle.push_back(triangles);
  v.world.resize(vertices);
  v.clip.resize(vertices);
  v.flags.resize(vertices);
  if (buffers.workers.size() < static_cast<std::size_t>(pool.size())) buffers.workers.resize(static_cast<std::size_t>(pool.size()));
  forEachRange(pool, frame.instances.size() == 0 ? 0 : vertices, [&](std::size_t begin, std::size_t end, int) {
    std::size_t instance = 0;
    for (std::size_t g = begin; g < end; ++g) {
      while (g >= v.firstVertex[instance + 1]) ++instance;
      const FrameInstance& in = frame.instances[instance];
      const Mesh& mesh = scene.meshes[static_cast<std::size_t>(in.mesh)];
      v.world[g] = glm::vec3(transformPoint(in.worldFromModel, mesh.positions[g - v.firstVertex[instance]]));
    }
  });
}

void shadowPass(ThreadPool& pool, FrameBuffers& buffers, const Scene& scene, const FrameInputs& frame, const FrameLight& light, int face,
                ShadowMaps& maps) {
  const glm::mat4& lightClipFromWorld = light.frustum.clipFromWorld[static_cast<std::size_t>(face)];
  const int layer = light.shadowLayer + face;
  const int size = maps.size;
  const float half = 0.5f * static_cast<float>(size);
  PassVertices& v = buffers.vertices;
  const std::size_t vertexCount = v.world.size();
  v.stride = 4;
  v.window.resize(vertexCount * 4);

  // Vertex stage: clip = lightClipFromWorld · (TM · p), both products in the fixed order.
  forEachRange(pool, vertexCount, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t g = begin; g < end; ++g) {
      const glm::vec4 clip = transformPoint(lightClipFromWorld, v.world[g]);
      v.clip[g] = clip;
      v.flags[g] = vertexFlags(clip);
      packWindow(clip, half, half, v.window.data() + 4 * g);
    }
  });

  const TileGrid grid{size, size, (size + kTileSize - 1) / kTileSize, (size + kTileSize - 1) / kTileSize};
  forEachRange(pool, v.firstTriangle.back(), [&](std::size_t begin, std::size_t end, int w) {
    binTriangles(scene, frame, v, grid, false, begin, end, buffers.workers[static_cast<std::size_t>(w)], nullptr);
  });

  float* depth = maps.layer(layer);
  std::uint8_t* dirty = maps.dirtyTiles(layer, kTileSize);
  std::atomic<int> next{0};
  pool.run([&](int) {
    for (int tile = next++; tile < grid.count(); tile = next++) {
      const int tx0 = (tile % grid.columns) * kTileSize, ty0 = (tile / grid.columns) * kTileSize;
      const int tx1 = std::min(tx0 + kTileSize, size) - 1, ty1 = std::min(ty0 + kTileSize, size) - 1;
      bool any = false;
      for (const WorkerBins& bins : buffers.workers) any |= !bins.tiles[static_cast<std::size_t>(tile)].empty();
      // The map is cleared to 1 tile by tile, only where this frame or the last one drew.
      if (!any && !dirty[tile]) continue;
      for (int y = ty0; y <= ty1; ++y) std::fill_n(depth + static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + tx0, tx1 - tx0 + 1, 1.0f);
      dirty[tile] = any ? 1 : 0;
      for (const WorkerBins& bins : buffers.workers)
        for (const std::uint32_t index : bins.tiles[static_cast<std::size_t>(tile)]) {
          const BinnedTriangle& t = bins.triangles[index];
          int minX, minY, maxX, maxY;
          if (!boundsWithin(t, tx0, ty0, tx1, ty1, minX, minY, maxX, maxY)) continue;
          InterpolationVertex iv[3];
          for (int k = 0; k < 3; ++k) {
            const float* p = bins.vertex(v, t.vertex[k]);
            iv[k] = {p[0], p[1], p[2], p[3], nullptr};
          }
          const Interpolation interpolation(iv[0], iv[1], iv[2]);
          rasterizeBlocks(t, minX, minY, maxX, maxY, [&](int px, int py) {
            const float z = interpolation.depthAt(px, py);
            float& stored = depth[static_cast<std::size_t>(py) * static_cast<std::size_t>(size) + static_cast<std::size_t>(px)];
            if (z < stored) stored = z;
          });
        }
    }
  });
}

}  // namespace facet::cpu
