#version 450 core
// Shadow pass 1: depth only, from the light, one array layer per light face
// (renderer/PIPELINE.md, "Lights" and "Rasterization"); an alpha-masked draw also passes
// what its alpha is made of, so that what the mask cuts away casts no shadow.
#include "transform.glsl"

uniform mat4 lightClipFromWorld;  // PM·EM of the light's face
uniform mat4 worldFromModel;      // TM

layout(location = 0) in vec3 position;  // model space
layout(location = 2) in vec2 texcoord;  // TEXCOORD_0 (read only when masked)
layout(location = 5) in vec2 texcoord1; // TEXCOORD_1 (0, 0 when the mesh has none)
layout(location = 3) in vec4 color0;    // COLOR_0 (read only when masked)

out vec4 st;  // TEXCOORD_0 in xy, TEXCOORD_1 in zw
out vec4 vertexColor;

void main() {
  gl_Position = transformPoint(lightClipFromWorld, transformPoint(worldFromModel, position).xyz);
  st = vec4(texcoord, texcoord1);
  vertexColor = color0;
}
