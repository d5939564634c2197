#pragma once
// The memory one pass of a CPU frame works in, kept by the renderer from
// frame to frame so that a frame allocates nothing once the sizes settle.
//
// A pass runs in three parallel phases (renderer/cpu/cpu_renderer.cpp):
//   1. vertex stage, once per vertex: window vertices packed as
//      x, y, z, 1/w, varyings... (`stride` floats) plus the clip coordinates
//      and clip mask the clipper needs;
//   2. primitive stage, on contiguous ranges of the triangle list (one per
//      worker): clip, snap, cull, and bin each triangle to the 64×64 tiles
//      its bounding box touches, in triangle order;
//   3. tiles, one worker each: the bins of worker 0, then worker 1, ..., so
//      each pixel sees its triangles in the order they were submitted.
#include <algorithm>
#include <cstdint>
#include <iterator>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "cpu/clipper.h"
#include "cpu/interpolation.h"
#include "shading/draw_uniforms.h"
#include "shading/lighting.h"
#include "cpu/line_raster.h"
#include "cpu/triangle_setup.h"
#include "image/color_buffer.h"
#include "scene/memory_budget.h"

namespace facet::cpu {

inline constexpr int kTileShift = 6;
inline constexpr int kTileSize = 1 << kTileShift;  // pixels

// A triangle after clipping, snapping and culling.
struct BinnedTriangle {
  SnappedTriangle snapped;       // on the 1/256 grid, set-up order, and which side faces the eye
  std::uint32_t vertex[3];       // packed window vertices in set-up order (kClippedVertex: the worker's clipped store)
  std::uint32_t instance;        // index into FrameInputs::instances
  std::uint32_t triangle;        // index in the frame's triangle list (instances in order); the clipper's pieces share it
};
inline constexpr std::uint32_t kClippedVertex = 0x80000000u;

// Vertex flags: the clip mask (bits 0-5), and kNotFinite.
inline constexpr std::uint8_t kNotFinite = 0x80;

struct PassVertices {
  int stride = 4;                      // floats per packed window vertex
  std::vector<float> window;           // packed: x, y, z, 1/w, varyings
  std::vector<glm::vec4> clip;         // clip coordinates
  std::vector<std::uint8_t> flags;     // clip mask | kNotFinite
  std::vector<glm::vec3> world;        // world positions (flat shading; the shadow pass's faces share them)
  std::vector<std::size_t> firstVertex, firstTriangle;  // per instance, and the totals last

  const float* at(std::uint32_t v) const { return window.data() + static_cast<std::size_t>(v) * static_cast<std::size_t>(stride); }
};

// The memory budget prices a vertex at kFrameBytesPerVertex: the most these take.
static_assert((4 + kMaxVaryings) * sizeof(float) + sizeof(glm::vec4) + sizeof(std::uint8_t) + sizeof(glm::vec3) <= kFrameBytesPerVertex);

struct WorkerBins {
  std::vector<BinnedTriangle> triangles;
  std::vector<float> clipped;                        // packed window vertices the clipper made
  std::vector<Illumination> flat;                    // flat shading: front, back per triangle
  std::vector<std::vector<std::uint32_t>> tiles;     // per tile: indices into `triangles`, in order
  std::vector<WindowVertex> scratch;                 // the clipper's output
  struct TileTriangle {                              // a triangle the lit pass met in the tile, set up once
    // Set up in place (emplace_back): an Interpolation is some 400 bytes, a copy per triangle and tile.
    TileTriangle(const InterpolationVertex (&vertices)[3], const WorkerBins* from, std::uint32_t at)
        : interpolation(vertices[0], vertices[1], vertices[2]), bins(from), index(at) {}
    Interpolation interpolation;
    const WorkerBins* bins;                          // whose `triangles` holds it
    std::uint32_t index;
  };
  struct TileScratch {                               // the lit pass's tile: z-buffer and winning triangle
    // The arrays the shading loop reads a run of pixels from (id, fragment,
    // alpha) have room for sixteen past the tile's last pixel: it reads a
    // run's sixteen at once, wherever the run starts (lit_pass.cpp,
    // phong_lanes.h). What that room holds is never used (it is set, not left unwritten).
    static constexpr int kRunSlack = 16;
    TileScratch() {
      std::fill(std::end(id) - kRunSlack, std::end(id), 0u);
      std::fill(std::end(fragment) - kRunSlack, std::end(fragment), 0u);
      std::fill(std::end(alpha) - kRunSlack, std::end(alpha), 0.0f);
    }
    float depth[kTileSize * kTileSize];
    std::uint32_t id[kTileSize * kTileSize + kRunSlack];  // index into `triangles`
    std::vector<TileTriangle> triangles;
    // Transparency: the tile's blended triangles in their drawing order (their
    // ids and pixel boxes), then, one triangle at a time, which pixels its
    // fragments reach past the depth test and their α.
    struct Blended {
      std::uint32_t id;
      PixelBox box;
    };
    std::vector<Blended> blended;
    std::uint32_t fragment[kTileSize * kTileSize + kRunSlack];  // the id of the blended triangle drawn there, or none
    float alpha[kTileSize * kTileSize + kRunSlack];
    // The tile's linear colours where the lit pass resolves each tile as it finishes it (LitPassOutput::image).
    glm::vec4 pixels[kTileSize * kTileSize];
  } tile;

  const float* vertex(const PassVertices& v, std::uint32_t ref) const {
    return ref & kClippedVertex ? clipped.data() + static_cast<std::size_t>(ref & ~kClippedVertex) * static_cast<std::size_t>(v.stride)
                                : v.at(ref);
  }
};

struct TileRect {
  int x0, y0, x1, y1;  // pixels, inclusive
};

struct TileGrid {
  int width = 0, height = 0;     // pixels
  int columns = 0, rows = 0;     // tiles

  static TileGrid over(int width, int height) {
    return {width, height, (width + kTileSize - 1) / kTileSize, (height + kTileSize - 1) / kTileSize};
  }
  int count() const { return columns * rows; }
  TileRect rect(int tile) const {
    const int x0 = (tile % columns) * kTileSize, y0 = (tile / columns) * kTileSize;
    return {x0, y0, std::min(x0 + kTileSize, width) - 1, std::min(y0 + kTileSize, height) - 1};
  }
};

// Triangles binned to `tile` by all workers.
inline std::size_t trianglesInTile(const std::vector<WorkerBins>& workers, int tile) {
  std::size_t n = 0;
  for (const WorkerBins& bins : workers) n += bins.tiles[static_cast<std::size_t>(tile)].size();
  return n;
}

struct FrameBuffers {
  PassVertices vertices;
  std::vector<DrawUniforms> draws;  // each instance's, found once per lit pass
  std::vector<WorkerBins> workers;
  std::vector<DrawnLine> lines;  // the lit pass's segments and points (line_pass.h)
  std::vector<std::uint32_t> visible;  // hsr = scanline: each pixel's polygon (scanline_zbuffer.h)
  // Transparency: the lit pass's triangle order (the opaque ones, then
  // FrameInputs::transparentOrder).
  std::vector<std::uint32_t> submission;
  // Volume ray casting: each pixel's window z after the opaque surfaces and lines, where its rays stop.
  std::vector<float> depth;
  // Pixels Phong's lighting takes at a time: 8, 4 or 1 (lane_width.h).
  int lanes = 1;
};

}  // namespace facet::cpu
