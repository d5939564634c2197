#version 450 core
// The background colour, encoded and quantized exactly as a lit pixel is.
#include "frame_block.glsl"
#include "srgb_encode.glsl"

layout(location = 0) out vec4 color;

void main() {
  color = vec4(encodeSrgb(frame.background.rgb), 1.0);
}
