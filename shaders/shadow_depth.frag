#version 450 core
// Shadow pass 1: the window z of each fragment is all it writes, unless the
// alpha mask discards it (FACET_MASKED; its derivatives are the shadow map's).
#include "frame_block.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "texture.glsl"
#include "procedural.glsl"
#include "draw_uniforms.glsl"

in vec4 st;  // TEXCOORD_0 in xy, TEXCOORD_1 in zw
in vec4 vertexColor;

void main() {
  Texcoords t = texcoordsAt(st);
  if (!alphaKept(baseColorAt(t, vertexColor, vec3(0.0)).a)) discard;
}
