#pragma once
// The interface both backends implement: a Scene and its FrameInputs in, an
// Image out. Backends consume FrameInputs; they never compute a matrix.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec4.hpp>

#include "common/error.h"
#include "image/image.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet {

struct PassTiming {
  std::string pass;       // "shadow pass (light 0)", "lit pass", "read-back", ...
  double milliseconds = 0;
};

// Passes the GL renderers (the backend, bench's lean peer) time once for a
// scene or a set of programs, not every frame: readers of the timings (facet
// bench, facet view --bench-orbit) tell them from the frame's by these names.
inline constexpr char kSceneUploadPass[] = "scene upload";
inline constexpr char kShaderCompilePass[] = "shader compile + link";

// Pass 1's output of a frame (Renderer::shadowMaps): every shadow map, one
// layer per light face in FrameLight::shadowLayer order (the lights in
// order; a point light's faces +x, -x, +y, -y, +z, -z).
struct ShadowMapTexels {
  int size = 0;               // S: each layer is S×S texels
  int layers = 0;             // FrameInputs::shadowLayerCount
  std::vector<float> texels;  // layer after layer, each bottom row first; window z, 1 where nothing was drawn
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

  // The stages of a frame (renderer/PIPELINE.md, section 6, "Stages"; the
  // viewer's and `render --output-stage`'s pictures of them come from
  // render/stage.h). A backend that does not draw one throws facet::Error
  // naming the stage and itself: the ray tracer and the readable reference
  // keep these defaults.
  //
  // The lit pass's z-buffer after the frame, at the pixel centres (the
  // samples of anti-aliasing are not drawn): width × height window z, bottom
  // row first, the value the LESS test kept (lines and points included), 1
  // where nothing was drawn.
  virtual std::vector<float> depthBuffer(const Scene& /*scene*/, const FrameInputs& /*frame*/) { throw notDrawn("depth"); }
  // The frame's shadow maps as pass 1 draws them (the maps a renderer keeps
  // across frames, pipeline/shadow_pass_key.h, when they are this frame's).
  virtual ShadowMapTexels shadowMaps(const Scene& /*scene*/, const FrameInputs& /*frame*/) { throw notDrawn("shadow-map"); }
  // The normal each pixel is shaded with (renderer/PIPELINE.md, section 6,
  // "Stages"), at the pixel centres: width × height (N, 1), world space,
  // bottom row first; (0, 0, 0, 0) where no opaque triangle was kept.
  virtual std::vector<glm::vec4> normals(const Scene& /*scene*/, const FrameInputs& /*frame*/) { throw notDrawn("normals"); }

  // Forgets the shadow maps kept from earlier frames (pipeline/shadow_pass_key.h):
  // the next frame draws its maps, as a one-frame `facet render` does. What
  // `facet bench` calls before each timed frame, so that a backend that keeps
  // its maps is timed on the same work as one that does not.
  virtual void forgetShadowMaps() {}

  // Hands back the image of a frame this renderer returned, once the caller
  // is done with it: the next frame is written into its storage rather than
  // into fresh memory, whose pages the kernel clears on first touch (13 % of
  // a 1920x1080 CPU frame's time: facet bench, the viewer).
  void recycle(Image&& image) { spare_ = std::move(image); }

 protected:
  Error notDrawn(const std::string& stage) const { return Error("the " + stage + " stage is not drawn by " + description()); }
  // The recycled image (empty if none): a frame's storage, which the
  // backend sizes (Image::resize) and then writes every pixel of.
  Image recycledImage() { return std::exchange(spare_, Image()); }

 private:
  Image spare_;
};

}  // namespace facet
