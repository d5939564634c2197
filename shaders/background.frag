#version 450 core
// The background colour, encoded and quantized exactly as a lit pixel is.
#include "frame_block.glsl"
#include "transform.glsl"
#include "texture.glsl"
#include "draw_uniforms.glsl"
#include "lighting.glsl"

layout(location = 0) out vec4 color;

void main() {
  color = vec4(encodeSrgb(frame.background.rgb), 1.0);
}
