#version 450 core
// The background into the linear colour buffer, as a lit pixel is: the
// background colour, or the environment map in the pixel's view direction.
#include "frame_block.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "texture.glsl"
#include "environment.glsl"

uniform vec2 viewportSize;     // W, H
uniform float backgroundAlpha;  // alpha of empty pixels

layout(location = 0) out vec4 color;

void main() {
  color = vec4(backgroundAt(gl_FragCoord.xy, viewportSize), backgroundAlpha);
}
