// The uniforms of one draw of the lit pass (one mesh instance), set by
// renderer/gl/frame_renderer.cpp from FrameInputs::instances and ::materials,
// and the two textures the lit pass reads (with texelFetch only).
// Needs frame_block.glsl, srgb.glsl, texture.glsl and procedural.glsl before it.

uniform mat4 clipFromModel;        // PM·EM·TM
uniform mat4 worldFromModel;       // TM
uniform mat3 normalMatrix;         // (TM^T)^-1, upper 3x3
uniform CourseMaterial material;   // k_e, k_a, k_d, k_s, n
uniform vec3 baseColorFactor;      // O_d without its texture, linear RGB
uniform float baseAlpha;           // its alpha
uniform bool unlit;                // KHR_materials_unlit: the colour is O_d, no illumination
uniform float alphaCutoff;         // alphaMode MASK: the least alpha a fragment keeps
uniform ivec4 baseColorSampler;    // its texture's magFilter, minFilter, wrapS, wrapT: scene/scene.h's enum values
uniform vec3 baseColorTransform[2];// its KHR_texture_transform: the rows of st' = M·(s, t, 1)
uniform int baseColorSet;          // the texture coordinates it reads: 1 TEXCOORD_1, else TEXCOORD_0
uniform ivec4 mapSets;             // those of the metallic-roughness, occlusion, emissive and normal textures

uniform ivec4 metallicRoughnessSampler, occlusionSampler, emissiveSampler;  // shading=pbr's maps' samplers, as baseColorSampler
uniform float occlusionStrength;   // ao = 1 + strength·(R - 1)
uniform ivec4 mapsSrgb;            // 1 where a map's texels are sRGB colour: metallic-roughness, occlusion, emissive, normal
uniform ivec4 normalMapSampler;    // the normal texture's sampler, as baseColorSampler
uniform float normalScale;         // scales its x and y

layout(binding = 0) uniform sampler2DArray shadowMaps;  // pass 1: one S×S depth layer per light face
layout(binding = 1) uniform usampler2D baseColorTexture; // sRGB-encoded bytes (GL_RGBA8UI), bottom row first
layout(binding = 3) uniform usampler2D metallicRoughnessMap;  // data bytes: G roughness, B metallic (shading=pbr)
layout(binding = 4) uniform usampler2D occlusionMap;          // data bytes: R occlusion
layout(binding = 5) uniform usampler2D emissiveMap;           // sRGB-encoded bytes
layout(binding = 6) uniform usampler2D normalMap;             // data bytes: tangent-space normal (Phong and pbr)

// Both texture coordinate sets at the fragment, st.xy TEXCOORD_0 and st.zw
// TEXCOORD_1, with their derivatives dFdx(st) and dFdy(st); (0, 0) for a set
// the mesh lacks (renderer/PIPELINE.md, "Textures").
struct Texcoords {
  vec4 st, dx, dy;
};

// Fragment stages only (a macro, so that vertex stages never see dFdx), in
// uniform control flow, before anything can branch.
#define texcoordsAt(st) Texcoords(st, dFdx(st), dFdy(st))

// A texture reference's set (1: TEXCOORD_1, else TEXCOORD_0) and its derivatives (ds/dx, dt/dx, ds/dy, dt/dy).
vec2 setOf(Texcoords t, int set) {
  return set == 1 ? t.st.zw : t.st.xy;
}
vec4 derivativesOf(Texcoords t, int set) {
  return set == 1 ? vec4(t.dx.zw, t.dy.zw) : vec4(t.dx.xy, t.dy.xy);
}

// O_d = factor · COLOR_0 · texel at the base colour texture's set of t, and
// its alpha (factor.a · COLOR_0.a) · texel.a (renderer/PIPELINE.md,
// "Textures"); with FACET_PROCEDURAL, the texel is the pattern's at
// modelPoint. FACET_COLORED: the draw's mesh has COLOR_0; FACET_TEXTURED:
// its material has a base colour texture and its mesh that texture's set.
vec4 baseColorAt(Texcoords t, vec4 vertexColor, vec3 modelPoint) {
  precise vec3 O = baseColorFactor;
  precise float alpha = baseAlpha;
#if FACET_COLORED
  O = O * vertexColor.rgb;
  alpha = alpha * vertexColor.a;
#endif
#if defined(FACET_PROCEDURAL) && FACET_PROCEDURAL
  // A procedural texture in place of the base colour texture (grey, alpha 1); frame.ambient.y is its scale k.
  O = O * proceduralGrey(FACET_PROCEDURAL, modelPoint, frame.ambient.y);
#elif FACET_TEXTURED
  // KHR_texture_transform: st' by the 2×3 matrix, the derivatives by its linear part (renderer/shading/texture.h).
  vec3 a = baseColorTransform[0], b = baseColorTransform[1];
  vec2 st = setOf(t, baseColorSet);
  vec4 stDerivatives = derivativesOf(t, baseColorSet);
  precise vec2 uv = vec2((a.x * st.x + a.y * st.y) + a.z, (b.x * st.x + b.y * st.y) + b.z);
  precise vec4 d = vec4(a.x * stDerivatives.x + a.y * stDerivatives.y, b.x * stDerivatives.x + b.y * stDerivatives.y,
                        a.x * stDerivatives.z + a.y * stDerivatives.w, b.x * stDerivatives.z + b.y * stDerivatives.w);
  vec4 texel = sampleTexture(baseColorTexture, true, baseColorSampler, uv, d);
  O = O * texel.rgb;
  alpha = alpha * texel.a;
#endif
  return vec4(O, alpha);
}

// k_e·E: the emissive texture's RGB at its set of t, times k_e
// (renderer/PIPELINE.md, "Materials"). Mirror: emissionAt in
// renderer/shading/texture.h. For draws with FACET_EMISSIVE_MAP.
vec3 emissionAt(Texcoords t) {
  precise vec3 e = material.emissive * sampleTexture(emissiveMap, mapsSrgb.z != 0, emissiveSampler, setOf(t, mapSets.z), derivativesOf(t, mapSets.z)).rgb;
  return e;
}

// The material Gouraud and flat shading sum at a vertex or a triangle: k_e = 0
// where an emissive texture adds k_e·E at the pixel instead.
CourseMaterial summedMaterial() {
  CourseMaterial m = material;
#if FACET_EMISSIVE_MAP
  m.emissive = vec3(0.0);
#endif
  return m;
}

// alphaMode MASK: a fragment is kept when its alpha is at least the cutoff
// (NaN discards). Mirror: renderer/cpu/alpha_mask.h. FACET_MASKED: the
// draw's material is masked; without it nothing is discarded, and the
// program keeps llvmpipe's early depth test.
bool alphaKept(float alpha) {
#if FACET_MASKED
  return alpha >= alphaCutoff;
#else
  return true;
#endif
}
