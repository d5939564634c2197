#version 450 core
// Which triangle each pixel keeps (Renderer::visibleTriangles): the lit
// pass's clip coordinates, bit for bit, so the same pixels and depths.
#include "transform.glsl"

uniform mat4 clipFromModel;  // PM·EM·TM

layout(location = 0) in vec3 position;  // model space

void main() {
  gl_Position = transformPoint(clipFromModel, position);
}
