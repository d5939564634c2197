#pragma once
// The frames some stages of renderer/PIPELINE.md ("Stages") are
// drawn from: one transformation of FrameInputs each, written once and used
// by every backend, so that a stage needs no drawing code of its own beyond
// what it reads back.
#include <cstddef>

#include "pipeline/frame_inputs.h"

namespace facet {

// `render --output-stage light-N`: the frame lit by light `light` alone. Its
// only light is that one (its shadow maps the frame's first layers, drawn as
// the frame draws them); I_a = 0; every material's k_e = 0 and no emissive
// texture; an unlit material's O_d is 0 (its colour is light it gives, as
// emission is), its alpha kept; and no environment map, which lights a
// surface as ambient light does (reflection, shading=pbr's image-based
// ambient): empty pixels show the background colour. Everything else is the
// frame's. Throws facet::Error when the frame has no such light.
FrameInputs lightAlone(const FrameInputs& frame, std::size_t light);

// What the normals stage draws of `frame`: one pass at the pixel centres
// (no samples, no area averaging), no lights and no shadow maps (the normal
// reads neither), and a Gouraud frame as a Phong one without normal textures
// or the bump map, which Gouraud shading does not read: its interpolated
// vertex normal is Phong's.
FrameInputs normalsFrame(const FrameInputs& frame);

}  // namespace facet
