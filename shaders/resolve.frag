#version 450 core
// The resolve (renderer/PIPELINE.md, "The colour buffer and the
// resolve"): the lit pass's linear RGBA, read texel for texel, encoded
// once into the RGBA8 image, straight (a premultiplied buffer's colour
// divided by its alpha first). Mirror: renderer/shading/resolve.cpp.
#include "resolved.glsl"

uniform bool premultiplied;  // the buffer holds C·a (blending=premultiplied, or a sum of samples)
uniform float samples;       // the passes summed into it: anti-aliasing's box filter divides by their count

layout(binding = 8) uniform sampler2D linearColor;  // the RGBA32F colour buffer (kResolveUnit)

layout(location = 0) out vec4 color;

void main() {
  precise vec4 mean = texelFetch(linearColor, ivec2(gl_FragCoord.xy), 0) / samples;
  color = resolved(mean, premultiplied);
}
