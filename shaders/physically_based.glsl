// shading=pbr: glTF 2.0's metallic-roughness BRDF as the Khronos glTF Sample
// Viewer evaluates it (renderer/PIPELINE.md, "Physically based").
// Mirror: renderer/shading/physically_based.h and renderer/pipeline/microfacet.h,
// the same functions with the same float operations, each result `precise`.
// Needs lighting.glsl (and what it needs) and environment.glsl before it.
//
//   L_o = Σ (S·f_att)·((N·L)·I_p)·((1 - F)·c_diff/π + F·D·Vis)
//       + ao·(c_diff·E(N)/π + prefiltered(R, r)·(F0·A + B)) + k_e

const float kPi = 3.14159274;      // π rounded to float (renderer/pipeline/microfacet.h)
const float kDielectricF0 = 0.04;  // a dielectric's reflectance at normal incidence
const float kMinAlpha = 0.001;     // α = max(r², this): D stays finite on a mirror

// What one pixel's material gives the BRDF.
struct PbrSurface {
  vec3 baseColor;  // O_d, linear
  float metallic;  // m
  float roughness; // r
  float occlusion; // ao: scales the ambient light
  vec3 emissive;   // k_e
};

// The pixel's surface: O_d, the material's factors times its maps, each read
// at its own set of t (mapSets) with that set's derivatives (no texture
// transform), the maps the draw's variant has (FACET_*_MAP: the material has
// it, the mesh its set):
//   r·G, m·B of the metallic-roughness map; ao = 1 + strength·(R - 1); k_e·RGB of the emissive map.
PbrSurface pbrSurfaceAt(vec3 baseColor, Texcoords t) {
  PbrSurface s = PbrSurface(baseColor, material.metallic, material.roughness, 1.0, material.emissive);
#if FACET_METALLIC_ROUGHNESS_MAP
  vec4 texel = sampleTexture(metallicRoughnessMap, mapsSrgb.x != 0, metallicRoughnessSampler, setOf(t, mapSets.x), derivativesOf(t, mapSets.x));
  precise float r = s.roughness * texel.g, m = s.metallic * texel.b;
  s.roughness = r;
  s.metallic = m;
#endif
#if FACET_OCCLUSION_MAP
  precise float ao = 1.0 + occlusionStrength * (sampleTexture(occlusionMap, mapsSrgb.y != 0, occlusionSampler, setOf(t, mapSets.y), derivativesOf(t, mapSets.y)).r - 1.0);
  s.occlusion = ao;
#endif
#if FACET_EMISSIVE_MAP
  s.emissive = emissionAt(t);
#endif
  return s;
}

// F = F0 + (1 - F0)·x⁵, x = 1 - V·H, x⁵ = (x²·x²)·x (Schlick)
vec3 schlickFresnel(vec3 F0, float VdotH) {
  precise float x = 1.0 - VdotH;
  precise float x2 = x * x;
  precise float x5 = (x2 * x2) * x;
  precise vec3 F = F0 + (vec3(1.0) - F0) * x5;
  return F;
}

// D = α²/(π·(d·d)), d = (N·H)²·(α² - 1) + 1 (GGX)
float ggxDistribution(float NdotH, float alpha2) {
  precise float d = (NdotH * NdotH) * (alpha2 - 1.0) + 1.0;
  precise float D = alpha2 / (kPi * (d * d));
  return D;
}

// Vis = 0.5/(N·L·sqrt((N·V)²(1 - α²) + α²) + N·V·sqrt((N·L)²(1 - α²) + α²)) (Smith, height-correlated)
float smithVisibility(float NdotL, float NdotV, float alpha2) {
  precise float rest = 1.0 - alpha2;
  precise float towardV = NdotL * sqrt((NdotV * NdotV) * rest + alpha2);
  precise float towardL = NdotV * sqrt((NdotL * NdotL) * rest + alpha2);
  precise float Vis = 0.5 / (towardV + towardL);
  return Vis;
}

// The split-sum table of renderer/pipeline/split_sum.h, two (A, B) entries to a vec4:
// entry k = row·32 + column is splitSum[k / 2].xy for even k, .zw for odd k.
const int kSplitSumSize = 32;
layout(std140, binding = 2) uniform SplitSumTable {
  vec4 splitSum[kSplitSumSize * kSplitSumSize / 2];
};

vec4 splitSumEntry(int column, int row) {
  int k = row * kSplitSumSize + column;
  vec4 e = splitSum[k >> 1];
  return (k & 1) == 0 ? vec4(e.xy, 0.0, 0.0) : vec4(e.zw, 0.0, 0.0);
}

int splitSumIndex(float i) {
  return !(i >= 0.0) ? 0 : (i > float(kSplitSumSize - 1) ? kSplitSumSize - 1 : int(i));
}

// The split-sum factors (A, B) at roughness r and N·V: the table read LINEAR
// at x = N·V·31, y = r·31, indices clamped to [0, 31].
vec2 environmentBrdf(float roughness, float NdotV) {
  precise float x = NdotV * float(kSplitSumSize - 1), y = roughness * float(kSplitSumSize - 1);
  precise float x0 = floor(x), y0 = floor(y);
  precise float fx = x - x0, fy = y - y0;
  int i0 = splitSumIndex(x0), i1 = splitSumIndex(x0 + 1.0), j0 = splitSumIndex(y0), j1 = splitSumIndex(y0 + 1.0);
  return lerp(lerp(splitSumEntry(i0, j0), splitSumEntry(i1, j0), fx), lerp(splitSumEntry(i0, j1), splitSumEntry(i1, j1), fx), fy).xy;
}

#if defined(FACET_ENVIRONMENT) && FACET_ENVIRONMENT
// E(N)/π from the map's nine coefficients (frame.irradiance), each channel max(·, 0).
vec3 irradianceAt(vec3 N) {
  float x = N.x, y = N.y, z = N.z;
  precise vec3 e = ((((((((frame.irradiance[0].rgb + frame.irradiance[1].rgb * x) + frame.irradiance[2].rgb * y) + frame.irradiance[3].rgb * z) +
                        frame.irradiance[4].rgb * (x * y)) + frame.irradiance[5].rgb * (y * z)) + frame.irradiance[6].rgb * (x * z)) +
                     frame.irradiance[7].rgb * (x * x - y * y)) + frame.irradiance[8].rgb * (z * z));
  return vec3(maxZero(e.x), maxZero(e.y), maxZero(e.z));
}

// The prefiltered radiance in R for roughness r: mip level r·q, trilinear between levels.
vec3 prefilteredAt(vec3 R, float roughness) {
  int last = int(frame.environment.w);
  precise float lod = roughness * float(last);
  precise float whole = floor(lod);
  int k = whole < float(last) ? int(whole) : last;
  vec3 above = environmentAt(R, k);
  if (k == last) return above;
  return lerp(vec4(above, 0.0), vec4(environmentAt(R, k + 1), 0.0), lod - whole).rgb;
}
#endif

// L_o at world point P with unit normal N and unit view vector V, linear and unclamped.
vec3 shadePhysicallyBased(PbrSurface s, vec3 P, vec3 N, vec3 V) {
  vec3 baseColor = s.baseColor;
  float roughness = s.roughness;
  float m = s.metallic;
  precise vec3 cDiff = baseColor * (1.0 - m);
  precise vec3 F0 = vec3(kDielectricF0 * (1.0 - m)) + baseColor * m;
  precise float r2 = roughness * roughness;
  float alpha = r2 > kMinAlpha ? r2 : kMinAlpha;
  precise float alpha2 = alpha * alpha;
  float NdotV = maxZero(dot3(N, V));
  precise vec3 lambert = cDiff / kPi;
  precise vec3 color = vec3(0.0);
  for (int i = 0; i < FACET_LIGHT_COUNT; ++i) {  // skipping by an if, as illuminate does
    TowardLight toward = towardLight(i, P);
    vec3 L = toward.L;
    precise float NdotL = dot3(N, L);
    if (toward.reaches && NdotL > 0.0) {  // as the course's modes: nothing where N·L ≤ 0
      vec3 H = normalize3(L + V);
      float NdotH = maxZero(dot3(N, H)), VdotH = maxZero(dot3(V, H));
      vec3 F = schlickFresnel(F0, VdotH);
      precise float specular = ggxDistribution(NdotH, alpha2) * smithVisibility(NdotL, NdotV, alpha2);
      precise vec3 f = (vec3(1.0) - F) * lambert + F * specular;
      precise float S = shadowFactor(i, P, N, L);
      precise vec3 radiance = (S * toward.fAtt) * (NdotL * frame.lights[i].intensity.rgb);
      color = color + radiance * f;
    }
  }
  // Image-based ambient: the map's irradiance and prefiltered radiance, or I_a from every direction.
  vec2 ab = environmentBrdf(roughness, NdotV);
  precise vec3 specularWeight = F0 * ab.x + vec3(ab.y);
  vec3 diffuseLight = vec3(frame.ambient.x), specularLight = vec3(frame.ambient.x);
#if defined(FACET_ENVIRONMENT) && FACET_ENVIRONMENT
  diffuseLight = irradianceAt(N);
  precise vec3 R = (2.0 * dot3(N, V)) * N - V;
  specularLight = prefilteredAt(R, roughness);
#endif
  color = color + s.occlusion * (cDiff * diffuseLight + specularLight * specularWeight);
  precise vec3 result = color + s.emissive;
  return result;
}
