#version 450 core
// One triangle over the whole viewport, no vertex buffer: the background and the resolve.
void main() {
  vec2 corner = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID & 2) * 2 - 1));  // (-1,-1), (3,-1), (-1,3)
  gl_Position = vec4(corner, 0.0, 1.0);
}
