#version 450 core
// Shadow pass 1: the window z of each fragment is all it writes, unless the
// alpha mask discards it (FACET_MASKED; its derivatives are the shadow map's).
#include "frame_block.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "texture.glsl"
#include "procedural.glsl"
#include "draw_uniforms.glsl"

in vec2 st;
in vec4 vertexColor;

void main() {
  vec4 stDerivatives = vec4(dFdx(st), dFdy(st));
  if (!alphaKept(baseColorAt(st, stDerivatives, vertexColor, vec3(0.0)).a)) discard;
}
