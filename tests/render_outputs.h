#pragma once
// Renderer::render in the manner of AOVs (render/renderer.h): a frame gives
// the outputs it is asked for and only those, each as a call that asks for it
// alone gives it. The backends' tests (tests/pipeline, tests/gl) hold each
// backend to it.
#include <cstddef>
#include <iterator>

#include <doctest/doctest.h>

#include "pipeline/frame_inputs.h"
#include "render/renderer.h"
#include "scene/default_scene.h"

namespace facet::test {

// A frame small enough for the slowest backend, with shadow maps.
inline FrameInputs smallFrame(const Scene& scene) {
  RenderSettings s;
  s.width = 40;
  s.height = 30;
  s.shadows.mapSize = 64;
  return buildFrameInputs(scene, s);
}

inline constexpr FrameOutput kEveryOutput[] = {FrameOutput::Image, FrameOutput::TriangleIds, FrameOutput::FragmentCounts,
                                               FrameOutput::Depth, FrameOutput::ShadowMaps,  FrameOutput::Normals};
static_assert(std::size(kEveryOutput) == static_cast<std::size_t>(FrameOutput::Count), "every output");

// Whether `r` holds `output` (an image that is not empty).
inline bool holds(const RenderResult& r, FrameOutput output) {
  switch (output) {
    case FrameOutput::Image: return !r.image.empty();
    case FrameOutput::TriangleIds: return r.triangleIds.has_value();
    case FrameOutput::FragmentCounts: return r.fragmentCounts.has_value();
    case FrameOutput::Depth: return r.depth.has_value();
    case FrameOutput::ShadowMaps: return r.shadowMaps.has_value();
    case FrameOutput::Normals: return r.normals.has_value();
    case FrameOutput::Count: break;
  }
  return false;
}

// Each output `drawn` names, asked alone, comes back alone; asked together, each as alone.
inline void checkOutputs(Renderer& renderer, const FrameOutputs& drawn) {
  const Scene scene = makeDefaultScene();
  const FrameInputs frame = smallFrame(scene);
  for (const FrameOutput asked : kEveryOutput) {
    if (!drawn.has(asked)) continue;
    CAPTURE(kFrameOutputNames[static_cast<std::size_t>(asked)]);
    const RenderResult result = renderer.render(scene, frame, {asked});
    for (const FrameOutput output : kEveryOutput) CHECK(holds(result, output) == (output == asked));
  }
  const RenderResult image = renderer.render(scene, frame);  // the image unless told otherwise
  for (const FrameOutput output : kEveryOutput) CHECK(holds(image, output) == (output == FrameOutput::Image));
  const RenderResult both = renderer.render(scene, frame, {FrameOutput::Image, FrameOutput::TriangleIds});
  CHECK(both.image == image.image);
  CHECK(both.triangleIds == renderer.render(scene, frame, {FrameOutput::TriangleIds}).triangleIds);
  CHECK_FALSE(both.fragmentCounts);
}

}  // namespace facet::test
