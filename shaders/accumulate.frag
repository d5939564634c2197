#version 450 core
#extension GL_EXT_shader_framebuffer_fetch : require
// Anti-aliasing (renderer/PIPELINE.md, "Anti-aliasing"): one
// sample's colour buffer added, premultiplied, into the sum of the samples
// drawn before it, read at the pixel by framebuffer fetch. Mirror:
// accumulate in renderer/shading/resolve.cpp.
#include "blending.glsl"

layout(binding = 8) uniform sampler2D linearColor;  // this sample's RGBA32F colour buffer (kResolveUnit)
uniform bool premultiplied;                         // blending=premultiplied: it holds C·a already

layout(location = 0) inout vec4 sum;

void main() {
  precise vec4 added = sum + premultipliedOf(texelFetch(linearColor, ivec2(gl_FragCoord.xy), 0), premultiplied);
  sum = added;
}
