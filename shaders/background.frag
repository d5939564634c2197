#version 450 core
// The background into the linear colour buffer, as a lit pixel is: the
// background colour, or the environment map in the pixel's view direction;
// in a frame encoded as drawn, the levels the resolve would give it.
#include "frame_block.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "texture.glsl"
#include "environment.glsl"
#include "blending.glsl"
#include "resolved.glsl"

uniform vec2 viewportSize;     // W, H
uniform float backgroundAlpha;  // alpha of empty pixels
uniform bool premultiplied;     // blending=premultiplied: the buffer holds C·a
uniform vec2 sampleOffset;      // anti-aliasing: this pass's sample offset, in pixels
uniform bool levels;            // a frame encoded as drawn: the resolve's levels of what would be held

layout(location = 0) out vec4 color;

void main() {
  precise vec2 at = gl_FragCoord.xy + sampleOffset;  // the pixel's sample: its centre, moved by the pass's offset
  vec4 held = stored(backgroundAt(at, viewportSize), backgroundAlpha, premultiplied);
  color = levels ? resolved(held, premultiplied) : held;
}
