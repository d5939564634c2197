#pragma once
// The interface both backends implement: a Scene and its FrameInputs in, an
// Image out. Backends consume FrameInputs; they never compute a matrix.
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet {

struct PassTiming {
  std::string pass;       // "shadow pass (light 0)", "lit pass", "read-back", ...
  double milliseconds = 0;
};

struct RenderResult {
  Image image;                      // RGBA8, bottom row first, sRGB-encoded
  std::vector<PassTiming> timings;  // in the order the passes ran
  std::vector<std::string> notes;   // figures of the frame a backend reports (the scanline z-buffer's depth memory)
};

class Renderer {
 public:
  virtual ~Renderer() = default;
  // What renders: "cpu (2 threads)", "gl: llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6 via osmesa".
  virtual std::string description() const = 0;
  // Throws facet::Error when the frame cannot be rendered.
  virtual RenderResult render(const Scene& scene, const FrameInputs& frame) = 0;

  // Which triangle each pixel of the frame keeps after the z-buffer, for
  // tests that hold two backends' coverage together: width × height values,
  // bottom row first, 0 for the background, else 1 + the triangle's index in
  // the frame (instances in FrameInputs order, each mesh's triangles in
  // order; the pieces of a clipped triangle keep its index).
  virtual std::vector<std::uint32_t> visibleTriangles(const Scene& scene, const FrameInputs& frame) = 0;

  // The frame's depth complexity (renderer/PIPELINE.md, section 6, "Depth
  // complexity"): how many triangle fragments each pixel received from the
  // rasterizer, before any depth or alpha test, after clipping and culling.
  // width × height counts, bottom row first.
  virtual std::vector<std::uint32_t> fragmentCounts(const Scene& scene, const FrameInputs& frame) = 0;
};

}  // namespace facet
