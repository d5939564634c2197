#version 450 core
// Lit pass, Phong shading: positions and normals to world space here, the
// lighting per pixel in lit_phong.frag (renderer/PIPELINE.md, "Shading").
#include "frame_block.glsl"
#include "transform.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "texture.glsl"
#include "procedural.glsl"
#include "draw_uniforms.glsl"

layout(location = 0) in vec3 position;  // model space
layout(location = 1) in vec3 normal;    // model space, unit length
layout(location = 2) in vec2 texcoord;  // TEXCOORD_0 (0, 0 when the mesh has none)
layout(location = 5) in vec2 texcoord1; // TEXCOORD_1 (0, 0 when the mesh has none)
layout(location = 3) in vec4 color0;    // COLOR_0, linear RGBA (read only when the mesh has it)
layout(location = 4) in vec4 tangent;   // TANGENT, model space; (0, 0, 0, 1) when the mesh has none

out vec3 worldPosition;
out vec3 worldNormal;  // unit at the vertex; renormalized per pixel
out vec4 st;  // TEXCOORD_0 in xy, TEXCOORD_1 in zw
out vec4 vertexColor;
out vec3 modelPoint;      // procedural textures
out vec4 worldTangent;    // xyz: TM's upper 3×3 times the tangent; w: its side

void main() {
  gl_Position = transformPoint(clipFromModel, position);
  worldPosition = transformPoint(worldFromModel, position).xyz;
  worldNormal = normalize3(transformDirection(normalMatrix, normal));
  st = vec4(texcoord, texcoord1);
  vertexColor = color0;
  modelPoint = position;
  worldTangent = vec4(transformDirection(mat3(worldFromModel), tangent.xyz), tangent.w);
}
