#version 450 core
// Lines and points are unlit: O_d times the interpolated vertex colour, through the frame's fog.
#include "frame_block.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "fog.glsl"

uniform vec3 baseColorFactor;  // O_d, linear

in vec3 vertexColor;

layout(location = 0) out vec4 color;

void main() {
  color = vec4(fogged(baseColorFactor * vertexColor), 1.0);
}
