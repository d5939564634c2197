#version 450 core
// 1 + the triangle's index in the frame: the draw's first triangle plus
// gl_PrimitiveID (the index in the draw, which clipping does not change).
// A fragment the alpha mask discards keeps no triangle, as in the lit pass.
// The painter's algorithm draws runs of its order: firstTriangle is then the
// run's first position, and `painted` maps positions to triangles.
#include "frame_block.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "texture.glsl"
#include "procedural.glsl"
#include "draw_uniforms.glsl"

uniform uint firstTriangle;
uniform bool painted;
layout(std430, binding = 5) readonly buffer PaintersOrder { uint paintersOrder[]; };

in vec4 st;  // TEXCOORD_0 in xy, TEXCOORD_1 in zw
in vec4 vertexColor;

layout(location = 0) out uint id;

void main() {
  Texcoords t = texcoordsAt(st);
  if (!alphaKept(baseColorAt(t, vertexColor, vec3(0.0)).a)) discard;
  uint position = firstTriangle + uint(gl_PrimitiveID);
  id = (painted ? paintersOrder[position] : position) + 1u;
}
