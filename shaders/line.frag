#version 450 core
// Lines and points are unlit: O_d times the interpolated vertex colour, through the frame's fog.
#include "frame_block.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "fog.glsl"
#include "resolved.glsl"

uniform vec3 baseColorFactor;  // O_d, linear
uniform bool levels;           // a frame encoded as drawn: the resolve's levels of (C, 1)

in vec3 vertexColor;

layout(location = 0) out vec4 color;

void main() {
  vec4 held = vec4(fogged(baseColorFactor * vertexColor), 1.0);
  color = levels ? resolved(held, false) : held;
}
