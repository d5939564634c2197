// Pass 1 of the course's 2-pass shadow algorithm: a depth-only z-buffer pass
// from the light into an S×S float map, one per face.
#include <algorithm>

#include "cpu/binning.h"
#include "cpu/interpolation.h"
#include "cpu/passes.h"
#include "cpu/tile_raster.h"
#include "cpu/vertex_math.h"

namespace facet::cpu {

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

  const TileGrid grid = TileGrid::over(size, size);
  forEachRange(pool, v.firstTriangle.back(), [&](std::size_t begin, std::size_t end, int w) {
    binTriangles(scene, frame, v, grid, false, begin, end, buffers.workers[static_cast<std::size_t>(w)], nullptr);
  });

  float* depth = maps.layer(layer);
  std::uint8_t* dirty = maps.dirtyTiles(layer, kTileSize);
  forEachTile(pool, grid, [&](int, int tile, const TileRect& r) {
    const bool any = trianglesInTile(buffers.workers, tile) > 0;
    // The map is cleared to 1 tile by tile, only where this frame or the last one drew.
    if (!any && !dirty[tile]) return;
    for (int y = r.y0; y <= r.y1; ++y) std::fill_n(depth + static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + r.x0, r.x1 - r.x0 + 1, 1.0f);
    dirty[tile] = any ? 1 : 0;
    forEachTriangleInTile(buffers.workers, v, tile, r,
                          [&](const WorkerBins&, std::uint32_t, const BinnedTriangle& t, const InterpolationVertex (&vertices)[3],
                              const PixelBox& box) {
                            const Interpolation interpolation(vertices[0], vertices[1], vertices[2]);
                            rasterizeBlocks(t.snapped, box, [&](int px, int py) {
                              const float z = interpolation.depthAt(px, py);
                              float& stored = depth[static_cast<std::size_t>(py) * static_cast<std::size_t>(size) + static_cast<std::size_t>(px)];
                              if (z < stored) stored = z;
                            });
                          });
  });
}

}  // namespace facet::cpu
