#version 450 core
// 1 + the triangle's index in the frame: the draw's first triangle plus
// gl_PrimitiveID (the index in the draw, which clipping does not change).
uniform uint firstTriangle;

layout(location = 0) out uint id;

void main() {
  id = firstTriangle + uint(gl_PrimitiveID) + 1u;
}
