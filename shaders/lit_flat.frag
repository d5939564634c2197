#version 450 core
// Lit pass, flat shading: the triangle's illumination of the side seen, times
// O_d at this pixel (renderer/PIPELINE.md, "Shading").
#include "frame_block.glsl"
#include "transform.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "texture.glsl"
#include "procedural.glsl"
#include "draw_uniforms.glsl"
#include "environment.glsl"
#include "lighting.glsl"
#include "fog.glsl"
#include "blending.glsl"
#include "lit_output.glsl"

flat in vec3 frontDiffuse;
flat in vec3 frontSpecular;
flat in vec3 backDiffuse;
flat in vec3 backSpecular;
in vec4 st;  // TEXCOORD_0 in xy, TEXCOORD_1 in zw
in vec4 vertexColor;
in vec3 modelPoint;
#if FACET_NORMAL_OUTPUT
flat in vec3 faceNormal;  // the normals stage
#endif


void main() {
  Texcoords t = texcoordsAt(st);  // in uniform control flow, before anything can branch
  Illumination I = gl_FrontFacing ? Illumination(frontDiffuse, frontSpecular) : Illumination(backDiffuse, backSpecular);
  vec4 O = baseColorAt(t, vertexColor, modelPoint);
  if (!alphaKept(O.a)) discard;  // alpha mask (a no-op unless FACET_MASKED)
#if FACET_NORMAL_OUTPUT
  writeNormal(gl_FrontFacing ? faceNormal : -faceNormal);  // the normals stage: the side lit, unlit materials too
  return;
#endif
#if FACET_EMISSIVE_MAP
  precise vec3 specular = emissionAt(t) + I.specular;  // summed with k_e = 0 (summedMaterial)
  I.specular = specular;
#endif
  writeLit(fogged(unlit ? O.rgb : shade(I, O.rgb)), O.a);  // KHR_materials_unlit: O_d itself, through the fog (a select, as lit_phong.frag)
}
