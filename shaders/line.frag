#version 450 core
// Lines and points are unlit: O_d times the interpolated vertex colour.
#include "srgb.glsl"

uniform vec3 baseColorFactor;  // O_d, linear

in vec3 vertexColor;

layout(location = 0) out vec4 color;

void main() {
  color = encodeSrgb(baseColorFactor * vertexColor);
}
