#pragma once
// The interface every backend implements: a Scene, its FrameInputs and the
// outputs asked in; the image and those outputs out. Backends consume
// FrameInputs; they never compute a matrix.
#include <array>
#include <bitset>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
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

// Pass 1's output of a frame (RenderResult::shadowMaps): every shadow map, one
// layer per light face in FrameLight::shadowLayer order (the lights in
// order; a point light's faces +x, -x, +y, -y, +z, -z).
struct ShadowMapTexels {
  int size = 0;               // S: each layer is S×S texels
  int layers = 0;             // FrameInputs::shadowLayerCount
  std::vector<float> texels;  // layer after layer, each bottom row first; window z, 1 where nothing was drawn
};

// What a frame can give (renderer/PIPELINE.md, "Stages"), in the
// manner of a renderer's AOVs: the image, and the raw data that render/stage.h
// pictures. A render call draws only the outputs it is asked for.
enum class FrameOutput { Image, TriangleIds, FragmentCounts, Depth, ShadowMaps, Normals, Count };
// The name a backend refuses each by ("the depth stage is not drawn by ..."): its stage's.
inline constexpr std::array<std::string_view, static_cast<std::size_t>(FrameOutput::Count)> kFrameOutputNames = {
    "image", "triangle-id", "overdraw", "depth", "shadow-map", "normals"};
static_assert(!kFrameOutputNames.back().empty(), "a name for every FrameOutput");

// A set of outputs: what a render call asks for (the image alone unless
// told otherwise), or what a backend draws.
class FrameOutputs {
 public:
  FrameOutputs() : FrameOutputs({FrameOutput::Image}) {}
  FrameOutputs(std::initializer_list<FrameOutput> outputs);
  bool has(FrameOutput output) const { return set_.test(static_cast<std::size_t>(output)); }

 private:
  std::bitset<static_cast<std::size_t>(FrameOutput::Count)> set_;
};

// One render call's outputs: the image and each of the others when asked,
// none otherwise. Every per-pixel output is width × height values, bottom
// row first.
struct RenderResult {
  Image image;                      // RGBA8, bottom row first, sRGB-encoded; empty unless asked
  std::vector<PassTiming> timings;  // in the order the passes ran
  std::vector<std::string> notes;   // figures of the frame a backend reports (the scanline z-buffer's depth memory)

  // Which triangle each pixel keeps after the z-buffer, for tests that hold
  // two backends' coverage together: 0 for the background, else 1 + the
  // triangle's index in the frame (instances in FrameInputs order, each
  // mesh's triangles in order; the pieces of a clipped triangle keep its index).
  std::optional<std::vector<std::uint32_t>> triangleIds;
  // The depth complexity (renderer/PIPELINE.md, "Depth
  // complexity"): how many triangle fragments each pixel received from the
  // rasterizer, before any depth or alpha test, after clipping and culling.
  std::optional<std::vector<std::uint32_t>> fragmentCounts;
  // The lit pass's z-buffer after the frame, at the pixel centres (the
  // samples of anti-aliasing are not drawn): window z, the value the LESS
  // test kept (lines and points included), 1 where nothing was drawn.
  std::optional<std::vector<float>> depth;
  // The frame's shadow maps as pass 1 draws them (the maps a renderer keeps
  // across frames, pipeline/shadow_pass_key.h, when they are this frame's).
  std::optional<ShadowMapTexels> shadowMaps;
  // The normal each pixel is shaded with (renderer/PIPELINE.md, "Rasterization",
  // "Stages"), at the pixel centres: (N, 1), world space; (0, 0, 0, 0)
  // where no opaque triangle was kept.
  std::optional<std::vector<glm::vec4>> normals;
};

class Renderer {
 public:
  virtual ~Renderer() = default;
  // What renders: "cpu (2 threads)", "gl: llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6 via osmesa".
  virtual std::string description() const = 0;
  // The outputs `asked` names, each from the frame's own passes (the image's
  // timings and notes when it is asked). A backend that does not draw one
  // of them throws facet::Error naming its stage and the backend before it
  // draws anything (the ray tracer and the readable reference draw the
  // image, triangle ids and fragment counts); facet::Error too when the
  // frame cannot be rendered.
  virtual RenderResult render(const Scene& scene, const FrameInputs& frame, const FrameOutputs& asked = {}) = 0;

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
  // Throws the error that names the first output `asked` holds and `drawn`
  // (what this backend draws) does not: "the depth stage is not drawn by ...".
  void refuseUndrawn(const FrameOutputs& asked, const FrameOutputs& drawn) const;
  // The recycled image (empty if none): a frame's storage, which the
  // backend sizes (Image::resize) and then writes every pixel of.
  Image recycledImage() { return std::exchange(spare_, Image()); }

 private:
  Image spare_;
};

}  // namespace facet
