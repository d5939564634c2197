#version 450 core
// Segments and points (glTF's LINES, LINE_LOOP, LINE_STRIP, POINTS): the
// lit pass's clip coordinates, bit for bit, and the vertex colour, which
// llvmpipe interpolates along a segment (renderer/PIPELINE.md, "Rasterization",
// "Lines and points"). Mirror: renderer/cpu/line_pass.cpp.
#include "transform.glsl"

uniform mat4 clipFromModel;  // PM·EM·TM
uniform bool colored;        // the mesh has COLOR_0

layout(location = 0) in vec3 position;  // model space
layout(location = 3) in vec4 color0;    // COLOR_0

out vec3 vertexColor;

void main() {
  gl_Position = transformPoint(clipFromModel, position);
  vertexColor = colored ? color0.rgb : vec3(1.0);
}
