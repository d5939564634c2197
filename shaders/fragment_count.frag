#version 450 core
// The depth complexity (Renderer::fragmentCounts): every fragment adds 1,
// blended GL_ONE + GL_ONE into a 32-bit float with no depth test.
layout(location = 0) out float count;

void main() { count = 1.0; }
