// The lit pass's output (renderer/PIPELINE.md, "Transparency"):
// an opaque fragment writes (C, 1) into the linear colour buffer; a blended
// one (FACET_BLENDED) reads the buffer at its pixel (EXT_shader_framebuffer_fetch,
// which sees every earlier fragment there in primitive order) and blends into
// it by the frame's equation (FACET_PREMULTIPLIED). With FACET_LEVELS_OUTPUT
// (a frame nothing blends or averages, never blended) it writes what the
// resolve would make of (C, 1): its levels, into the RGBA8 image. With
// FACET_NORMAL_OUTPUT (the normals stage, never blended) the fragment
// writes (N, 1), the normal it is shaded with, instead. Mirror:
// renderer/cpu/lit_pass.cpp.
#include "resolved.glsl"

#if FACET_BLENDED
layout(location = 0) inout vec4 color;
uniform bool additiveBlend;  // the material adds its light (the additive equation)
#else
layout(location = 0) out vec4 color;
#endif

#if FACET_NORMAL_OUTPUT && !FACET_BLENDED
void writeNormal(vec3 N) {
  color = vec4(N, 1.0);
}
#endif

void writeLit(vec3 lit, float alpha) {
#if FACET_BLENDED
  color = blend(color, lit, alpha, FACET_PREMULTIPLIED != 0, additiveBlend);
#elif FACET_LEVELS_OUTPUT
  color = resolved(vec4(lit, 1.0), false);  // (C, 1) holds C either way: the division by 1 is exact
#else
  color = vec4(lit, 1.0);
#endif
}
