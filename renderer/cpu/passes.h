#pragma once
// The two passes of a CPU frame (the course's 2-pass shadow algorithm):
// pass 1 renders each shadow-casting light's depth maps, pass 2 shades the
// image. Each runs in the phases of frame_buffers.h on the renderer's
// threads; each pixel is written by one thread, in triangle order, so
// results do not depend on the thread count.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cpu/frame_buffers.h"
#include "common/function_ref.h"
#include "shading/shadow_maps.h"
#include "common/thread_pool.h"
#include "image/color_buffer.h"
#include "image/image.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet::cpu {

// Hands the grid's tiles to the workers, each next tile to whichever worker
// is free: work(worker, tile, its pixel rectangle).
void forEachTile(ThreadPool& pool, const TileGrid& grid, FunctionRef<void(int, int, const TileRect&)> work);

// Once per frame: instance offsets and world positions of every vertex
// (transformPoint(worldFromModel, p)), shared by all passes.
void prepareFrame(ThreadPool& pool, FrameBuffers& buffers, const Scene& scene, const FrameInputs& frame);

// Pass 1 for one face layer: depth of every triangle (no culling), LESS.
void shadowPass(ThreadPool& pool, FrameBuffers& buffers, const Scene& scene, const FrameInputs& frame, const FrameLight& light, int face,
                ShadowMaps& maps);

// What a lit pass writes besides the image, or in its place.
struct LitPassOutput {
  // Which triangle each pixel keeps (FrameOutput::TriangleIds; width ×
  // height, bottom row first), in place of the colour buffer, which is left alone.
  std::vector<std::uint32_t>* triangleIds = nullptr;
  // The fragments each pixel receives before any test (FrameOutput::FragmentCounts;
  // width × height, bottom row first, zeroed by the caller), and nothing else.
  std::vector<std::uint32_t>* fragmentCounts = nullptr;
  // The normals stage (FrameOutput::Normals, a frame from pipeline/stage_frames.h's
  // normalsFrame): (N, 1) in place of each opaque pixel's colour, in a colour
  // buffer the caller cleared to 0; no lines, points or blended triangles.
  bool normals = false;
  // FrameBuffers::depth holds the z-buffer after the frame (opaque triangles,
  // then lines and points); volume ray casting keeps it too.
  bool keepDepth = false;
  // Each tile is set to the frame's background (backgroundPixel: one colour,
  // or the environment map behind the scene) before its triangles are drawn,
  // while the tile is in the cache: the caller sizes `color` and clears nothing.
  bool background = false;
  // A single-sample frame with nothing drawn after the lit pass: each tile,
  // once drawn, is resolved into `image` (resolve.h's rule; the caller sizes
  // it) while it is in the cache, and `color` is left alone.
  Image* image = nullptr;
};

// Pass 2: z-buffer and shading into the linear colour buffer `color`
// (cleared by the caller to the background). Only the fragment that ends up in a pixel is shaded: a
// tile's triangles are first resolved with the z-buffer (LESS, in triangle
// order) to the last one that passed the test at each pixel, the one whose
// colour the pixel keeps; shading is a function of triangle and pixel alone.
void litPass(ThreadPool& pool, FrameBuffers& buffers, const Scene& scene, const FrameInputs& frame, const ShadowMaps& maps, ColorBuffer& color,
             const LitPassOutput& output = {});

}  // namespace facet::cpu
