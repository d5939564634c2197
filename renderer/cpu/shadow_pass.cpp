// Pass 1 of the course's 2-pass shadow algorithm: a depth-only z-buffer pass
// from the light into an S×S float map, one per face.
#include <algorithm>

#include "cpu/alpha_mask.h"
#include "cpu/binning.h"
#include "cpu/depth_rows.h"
#include "cpu/interpolation.h"
#include "cpu/passes.h"
#include "shading/texture.h"
#include "cpu/tile_raster.h"
#include "shading/lit_varyings.h"
#include "shading/transform.h"

namespace facet::cpu {

void shadowPass(ThreadPool& pool, FrameBuffers& buffers, const Scene& scene, const FrameInputs& frame, const FrameLight& light, int face,
                ShadowMaps& maps) {
  const glm::mat4& lightClipFromWorld = light.frustum.clipFromWorld[static_cast<std::size_t>(face)];
  const int layer = light.shadowLayer + face;
  const int size = maps.size;
  const float half = 0.5f * static_cast<float>(size);
  PassVertices& v = buffers.vertices;
  const std::size_t vertexCount = v.world.size();
  // An alpha-masked or blended material needs its texture coordinates and vertex alpha
  // (the flat layout's: uv, RGBA) to decide which fragments cast a shadow.
  bool anyMasked = false;
  for (const FrameInstance& instance : frame.instances) anyMasked = anyMasked || masksShadow(frame.materials[static_cast<std::size_t>(instance.material)]);
  const VaryingLayout mask = varyingLayout(ShadingMode::Flat);
  const int stride = anyMasked ? 4 + mask.count : 4;
  v.stride = stride;
  v.window.resize(vertexCount * static_cast<std::size_t>(stride));

  // Vertex stage: clip = lightClipFromWorld · (TM · p), both products in the fixed order.
  forEachRange(pool, vertexCount, [&](std::size_t begin, std::size_t end, int) {
    std::size_t i = 0;
    for (std::size_t g = begin; g < end; ++g) {
      const glm::vec4 clip = transformPoint(lightClipFromWorld, v.world[g]);
      v.clip[g] = clip;
      v.flags[g] = vertexFlags(clip);
      float* out = v.window.data() + static_cast<std::size_t>(stride) * g;
      packWindow(clip, half, half, out);
      if (!anyMasked) continue;
      while (g >= v.firstVertex[i + 1]) ++i;
      const Mesh& mesh = scene.meshes[static_cast<std::size_t>(frame.instances[i].mesh)];
      const std::size_t local = g - v.firstVertex[i];
      const glm::vec4 color = mesh.colors.empty() ? glm::vec4(1.0f) : mesh.colors[local];
      putTexcoords(out + 4, mask.uv, mesh, local);
      for (int c = 0; c < 4; ++c) out[4 + mask.color + c] = color[c];
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
                            Interpolation interpolation(vertices[0], vertices[1], vertices[2]);
                            const FrameInstance& instance = frame.instances[t.instance];
                            const CourseMaterial& material = frame.materials[static_cast<std::size_t>(instance.material)];
                            if (!material.castsShadow) return;
                            if (!masksShadow(material)) {
                              const auto texel = [&](int px, int py) {
                                return depth + static_cast<std::size_t>(py) * static_cast<std::size_t>(size) + static_cast<std::size_t>(px);
                              };
                              rasterizeBlocks(
                                  t.snapped, box,
                                  [&](int px, int py) {
                                    const float z = interpolation.depthAt(px, py);
                                    float& stored = *texel(px, py);
                                    if (z < stored) stored = z;
                                  },
                                  [&](int x0, int x1, int py) { lessRowOnLanes(buffers.lanes, interpolation.depthPlane(), x0, x1, py, texel(x0, py), nullptr, 0); });
                              return;
                            }
                            const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
                            const Texture* texture = baseColorTextureOf(scene, frame, material, mesh);
                            const bool colored = !mesh.colors.empty();
                            interpolation.setUpVaryings(mask.count);
                            rasterizeBlocks(t.snapped, box, [&](int px, int py) {
                              const float z = interpolation.depthAt(px, py);
                              float& stored = depth[static_cast<std::size_t>(py) * static_cast<std::size_t>(size) + static_cast<std::size_t>(px)];
                              if (z < stored && keepsFragment(material, texture, colored, mask, interpolation, px, py)) stored = z;
                            });
                          });
  });
}

}  // namespace facet::cpu
