#version 450 core
// Lit pass, Phong shading: the illumination equation at every pixel, with the
// interpolated normal renormalized (renderer/PIPELINE.md, "Shading"); with
// FACET_PBR, glTF's metallic-roughness BRDF in its place (shading=pbr).
#include "frame_block.glsl"
#include "transform.glsl"
#include "shading_math.glsl"
#include "srgb.glsl"
#include "texture.glsl"
#include "procedural.glsl"
#include "draw_uniforms.glsl"
#include "environment.glsl"
#include "lighting.glsl"
#include "physically_based.glsl"
#include "normal_mapping.glsl"
#include "bump_mapping.glsl"
#include "fog.glsl"
#include "blending.glsl"
#include "lit_output.glsl"

in vec3 worldPosition;
in vec3 worldNormal;
in vec4 st;  // TEXCOORD_0 in xy, TEXCOORD_1 in zw
in vec4 vertexColor;
in vec3 modelPoint;
in vec4 worldTangent;


void main() {
  Texcoords t = texcoordsAt(st);  // in uniform control flow, before anything can branch
  vec3 P = worldPosition;
  vec3 N = normalize3(worldNormal);
#if FACET_NORMAL_MAP
  // A normal texture bends the unit interpolated normal; the result is normalized as that one is.
  N = normalize3(normalMapped(N, worldTangent, t));
#endif
#if FACET_BUMP_MAP
  N = normalize3(bumped(N, worldTangent, st.xy));  // the course's bump mapping, after the normal texture
#endif
  if (!gl_FrontFacing) N = -N;  // two-sided lighting: a back face is drawn only where it is not culled
  vec4 O = baseColorAt(t, vertexColor, modelPoint);
  if (!alphaKept(O.a)) discard;  // alpha mask (a no-op unless FACET_MASKED)
#if FACET_NORMAL_OUTPUT
  writeNormal(N);  // the normals stage: N as lit below, unlit materials too
  return;
#endif
#if FACET_PBR
  vec3 shaded = shadePhysicallyBased(pbrSurfaceAt(O.rgb, t), P, N, viewVector(P));
#else
  CourseMaterial lit = material;
#if FACET_EMISSIVE_MAP
  lit.emissive = emissionAt(t);  // k_e·E in k_e's place
#endif
  vec3 shaded = shade(illuminate(lit, P, N, viewVector(P)), O.rgb);
#endif
  // KHR_materials_unlit: O_d itself, through the fog. A select, not an early
  // return: llvmpipe's code for the lit pass is faster without the branch.
  writeLit(fogged(unlit ? O.rgb : shaded), O.a);
}
