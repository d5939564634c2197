#pragma once
// The course's pipeline one triangle at a time, written to be read
// (course_pipeline.cpp): pass 1 into the shadow maps, pass 2's triangles,
// lines and points into a z-buffer and what it guards. The readable
// reference renderer (reference_renderer.h) draws its frames with it.
#include <cstdint>
#include <vector>

#include "image/color_buffer.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"
#include "shading/shadow_maps.h"

namespace facet::cpu::reference {

// A pass's z-buffer (window z, cleared to 1) and what it guards: the colour
// buffer, or which triangle each pixel keeps, or how many fragments it got.
struct Target {
  int width = 0, height = 0;
  std::vector<float> depth;
  ColorBuffer* color = nullptr;
  std::vector<std::uint32_t>* ids = nullptr;
  std::vector<std::uint32_t>* counts = nullptr;  // every fragment before any test, and nothing else
};

// Pass 1: every triangle of a material that casts shadows, unculled, into each face of each shadow-casting light.
ShadowMaps shadowPass(const Scene& scene, const FrameInputs& frame);

// Pass 2's triangles: the opaque ones (instances in order), the blended ones
// (FrameInputs::transparentOrder, back to front), or all of them in instance order.
enum class Drawn { Opaque, Blended, All };
void litPass(const Scene& scene, const FrameInputs& frame, const ShadowMaps& maps, Target& target, Drawn drawn);

// Pass 2's lines and points, after every opaque triangle: each instance's segments, then its points.
void linePass(const Scene& scene, const FrameInputs& frame, Target& target);

}  // namespace facet::cpu::reference
