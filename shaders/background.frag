#version 450 core
// The background into the linear colour buffer, as a lit pixel is: the
// background colour, or the environment map in the pixel's view direction.
#include "frame_block.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "texture.glsl"
#include "environment.glsl"
#include "blending.glsl"

uniform vec2 viewportSize;     // W, H
uniform float backgroundAlpha;  // alpha of empty pixels
uniform bool premultiplied;     // blending=premultiplied: the buffer holds C·a

layout(location = 0) out vec4 color;

void main() {
  color = stored(backgroundAt(gl_FragCoord.xy, viewportSize), backgroundAlpha, premultiplied);
}
