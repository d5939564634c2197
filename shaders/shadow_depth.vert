#version 450 core
// Shadow pass 1: depth only, from the light, one array layer per light face
// (renderer/PIPELINE.md, sections 4 and 6).
#include "transform.glsl"

uniform mat4 lightClipFromWorld;  // PM·EM of the light's face
uniform mat4 worldFromModel;      // TM

layout(location = 0) in vec3 position;  // model space

void main() {
  gl_Position = transformPoint(lightClipFromWorld, transformPoint(worldFromModel, position).xyz);
}
