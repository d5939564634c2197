#version 450 core
// The background, encoded exactly as a lit pixel is.
#include "frame_block.glsl"
#include "srgb.glsl"

layout(location = 0) out vec4 color;

void main() {
  color = encodeSrgb(frame.background.rgb);
}
