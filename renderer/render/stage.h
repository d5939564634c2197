#pragma once
// The stages of a frame one can look at (renderer/PIPELINE.md, "Rasterization",
// "Stages"): the image, the depth complexity, the z-buffer, the shadow maps,
// the normals, and the frame lit by one light. `facet render --output-stage
// NAME` writes one; a viewer lists what a frame can show (stageNames). The
// list, the names and the pictures are here, once; the backends give the raw
// data (Renderer::render's outputs: fragment counts, depth, shadow maps,
// normals), and light-N is a frame of its own (pipeline/stage_frames.h)
// rendered as any.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec4.hpp>

#include "image/image.h"
#include "pipeline/frame_inputs.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace facet {

enum class StageKind { Image, Overdraw, Depth, ShadowMap, Normals, Light, Count };
// The names `--output-stage` takes; Light's is "light-N".
inline constexpr std::array<std::string_view, static_cast<std::size_t>(StageKind::Count)> kStageKindNames = {
    "image", "overdraw", "depth", "shadow-map", "normals", "light"};
static_assert(!kStageKindNames.back().empty(), "a name for every StageKind");

struct Stage {
  StageKind kind = StageKind::Image;
  std::size_t light = 0;  // StageKind::Light: N of light-N, an index into FrameInputs::lights
  friend bool operator==(const Stage&, const Stage&) = default;
};

// "image", "overdraw", "depth", "shadow-map", "normals" or "light-N" (N a
// whole number, digits only). Throws facet::UsageError naming --output-stage
// and the names it takes.
Stage parseStage(std::string_view name);
// The name parseStage reads: "light-2" for the third light.
std::string stageName(Stage stage);
// The stages `frame` can show, in the order above: image, overdraw, depth
// (not under hsr=painter, which keeps no z-buffer), shadow-map (when it has
// shadow maps), normals, then light-0, light-1, ... for its lights. A
// backend may still refuse one it does not draw (the ray tracer draws no
// z-buffer).
std::vector<std::string> stageNames(const FrameInputs& frame);
// Throws when `frame` cannot show `stage`: facet::UsageError for a light the
// frame does not have ("--output-stage light-3: the frame has 1 light"),
// facet::Error naming the key for a frame without shadow maps and for depth
// under hsr=painter. What renderStage checks first, and a command before it
// loads a driver.
void checkStage(const FrameInputs& frame, Stage stage);

// The stage as an RGBA8 image (bottom row first), the backend's timings,
// and the figures of the stage as the first of `notes` (none for the
// image): the depth's window z range, the shadow maps' layout, ... Throws
// what checkStage throws, and facet::Error from a backend that does not
// draw the stage.
RenderResult renderStage(Renderer& renderer, const Scene& scene, const FrameInputs& frame, Stage stage);

// The greys of depth images: window z over [near, far] of the drawn values
// (z < 1) stretched to kNearGrey .. kFarGrey, z = 1 (nothing drawn) black.
// Perspective window z crowds near 1; the stretch spreads what a frame
// holds over the greys. The far end stays above black, so the farthest
// surface is not taken for the background.
inline constexpr int kNearGrey = 255;
inline constexpr int kFarGrey = 48;

struct DepthRange {
  float near = 1.0f, far = 1.0f;  // the smallest and the largest drawn z; both 1 when nothing was drawn
  std::size_t drawn = 0;          // values below 1
};
DepthRange depthRangeOf(const float* depth, std::size_t count);
// The grey level of window z `z` in `range`: kNearGrey at range.near, kFarGrey at range.far (linear between, rounded),
// 0 for z = 1 (and for NaN, which the z-buffer never keeps).
std::uint8_t depthGrey(float z, const DepthRange& range);

// RenderResult::depth as greys (width × height, bottom row first).
Image depthImage(const std::vector<float>& depth, int width, int height);

// RenderResult::shadowMaps as one strip: the layers side by side in layer order,
// each S×S and stretched over its own range, unless layers × S would pass
// kMaxImageSide: then each layer keeps every `downsample`-th texel in x and
// y (nearest), the smallest whole factor that fits. downsample: 1 when kept whole.
Image shadowMapImage(const ShadowMapTexels& maps, int& downsample);

// RenderResult::normals as RGB = (N + 1)/2 in 8 bits, floor(255·c + 0.5) of c
// clamped to [0, 1] (NaN to 0), alpha 255; black (alpha 255) where w = 0.
Image normalsImage(const std::vector<glm::vec4>& normals, int width, int height);

}  // namespace facet
