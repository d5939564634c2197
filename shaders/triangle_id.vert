#version 450 core
// Which triangle each pixel keeps (Renderer::visibleTriangles): the lit
// pass's clip coordinates, bit for bit, so the same pixels and depths; an
// alpha-masked draw also passes what its alpha is made of.
#include "transform.glsl"

uniform mat4 clipFromModel;  // PM·EM·TM

layout(location = 0) in vec3 position;  // model space
layout(location = 2) in vec2 texcoord;  // TEXCOORD_0 (read only when masked)
layout(location = 5) in vec2 texcoord1; // TEXCOORD_1 (0, 0 when the mesh has none)
layout(location = 3) in vec4 color0;    // COLOR_0 (read only when masked)

out vec4 st;  // TEXCOORD_0 in xy, TEXCOORD_1 in zw
out vec4 vertexColor;

void main() {
  gl_Position = transformPoint(clipFromModel, position);
  st = vec4(texcoord, texcoord1);
  vertexColor = color0;
}
