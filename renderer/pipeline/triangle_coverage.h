#pragma once
// The coverage of one chosen triangle of a frame (the viewer's picked
// triangle): the pixel centres it covers after clipping and culling, by the
// backends' own rasterizer, and which of them it keeps after the z-buffer.
// It is drawn as a frame of its own: a scene holding only that triangle,
// placed by its instance's TM, whose FrameOutput::FragmentCounts is 1 exactly
// where the triangle covers a pixel centre (renderer/PIPELINE.md, section
// 6, "Depth complexity"); both backends draw it, so their coverage of any
// triangle can be compared.
#include <cstdint>
#include <vector>

#include "image/image.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet {

struct SingleTriangle {
  Scene scene;
  FrameInputs frame;
};

// Triangle `triangle` of the frame (numbered as FrameOutput::TriangleIds: 1 + its index in the frame's triangle list) alone.
// Throws facet::Error for a number the frame does not have.
SingleTriangle singleTriangle(const Scene& scene, const FrameInputs& frame, std::uint32_t triangle);

// The picture: where the triangle covers a pixel centre (counts > 0), yellow
// where the full frame keeps it (kept[pixel] == triangle), dark orange where
// another surface hides it; black elsewhere. Bottom row first.
Image coverageImage(const std::vector<std::uint32_t>& counts, const std::vector<std::uint32_t>& kept, std::uint32_t triangle, int width,
                    int height);

}  // namespace facet
