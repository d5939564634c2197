// The course's illumination equation in GLSL.
// Mirror: renderer/cpu/lighting.cpp — the same functions, in the same order,
// with the same names and arguments. Change one, change the other.
//
//   I = k_e + k_a·I_a·O_d + Σ_lights S·f_att·(k_d·I_p·max(N·L, 0)·O_d + k_s·I_p·spec)
//
// Needs frame_block.glsl, transform.glsl and `uniform sampler2DArray shadowMaps;`
// (draw_uniforms.glsl) before it, and the program's specialization macros
// (renderer/gl/shader_variant.cpp): FACET_LIGHT_COUNT, FACET_LIGHT_KIND(i),
// FACET_LIGHT_SHADOWED(i), FACET_SPECULAR_MODEL, FACET_PCF_RADIUS. They hold
// the values the frame block also holds; compiled in, the branches that do
// not apply to this frame are gone (llvmpipe runs both sides of a branch).

// f_att = min(1, 1/(c1 + c2·d + c3·d²))
float attenuation(vec3 c, float d) {
  return min(1.0, 1.0 / (c.x + c.y * d + c.z * d * d));
}

// spec = max(R·V, 0)^n (Phong) or max(N·H, 0)^n (Blinn-Phong).
float specularTerm(vec3 N, vec3 L, vec3 V, float shininess, int model) {
  if (model == 0) {
    vec3 R = 2.0 * dot(L, N) * N - L;
    return pow(max(dot(R, V), 0.0), shininess);
  }
  vec3 H = normalize(L + V);
  return pow(max(dot(N, H), 0.0), shininess);
}

// Face of a point light's cube for P - P_light: largest |component|, ties to x, then y, then z.
int cubeFace(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}

// S of light i at P: PCF over (2r+1)² texels read with texelFetch; in shadow
// when z - bias > depth, bias = max(b_slope·(1 - N·L), b_min); outside the
// map or beyond its far plane counts as lit.
float shadowFactor(int i, vec3 P, vec3 N, vec3 L) {
  if (!FACET_LIGHT_SHADOWED(i)) return 1.0;
  int face = FACET_LIGHT_KIND(i) == kLightPoint ? cubeFace(P - frame.lights[i].positionKind.xyz) : 0;
  precise vec4 s = transformPoint(frame.lights[i].shadowFromWorld[face], P);
  if (!(s.w > 0.0)) return 1.0;
  vec3 uvz = s.xyz / s.w;
  if (!(uvz.z <= 1.0) || isnan(uvz.x) || isnan(uvz.y)) return 1.0;
  // Far outside the map every texel is outside too; the clamp keeps the texel
  // index an int without changing which texels a point inside reads.
  uvz.xy = clamp(uvz.xy, -1.0, 2.0);
  float bias = max(frame.shadowParams.x * (1.0 - dot(N, L)), frame.shadowParams.y);
  int size = int(frame.shadowParams.w), r = FACET_PCF_RADIUS;
  int tx = int(floor(uvz.x * float(size)));
  int ty = int(floor(uvz.y * float(size)));
  int layer = frame.lights[i].shadow.y + face;
  int lit = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      int x = tx + dx, y = ty + dy;
      if (x < 0 || y < 0 || x >= size || y >= size) ++lit;
      else if (!(uvz.z - bias > texelFetch(shadowMaps, ivec3(x, y, layer), 0).r)) ++lit;
    }
  return float(lit) / float((2 * r + 1) * (2 * r + 1));
}

// I split in the part O_d multiplies and the rest (Gouraud and flat apply a
// textured O_d per pixel):  I = O_d·diffuse + specular
//   diffuse  = k_a·I_a + Σ S·f_att·k_d·I_p·max(N·L, 0)
//   specular = k_e + Σ S·f_att·k_s·I_p·spec
struct Illumination {
  vec3 diffuse;
  vec3 specular;
};

// Illumination at world point P with unit normal N and unit view vector V.
Illumination illuminate(CourseMaterial material, vec3 P, vec3 N, vec3 V) {
  Illumination I;
  I.diffuse = vec3(material.ka * frame.ambientCounts.x);
  I.specular = material.emissive;
  for (int i = 0; i < FACET_LIGHT_COUNT; ++i) {
    int kind = FACET_LIGHT_KIND(i);
    vec3 L;
    float fAtt = 1.0;
    if (kind == kLightDirectional) {
      L = -frame.lights[i].directionCosCutoff.xyz;
    } else {
      vec3 toLight = frame.lights[i].positionKind.xyz - P;
      float d = length(toLight);
      L = toLight / d;
      fAtt = attenuation(frame.lights[i].attenuation.xyz, d);
    }
    if (kind == kLightSpot && !(dot(-L, frame.lights[i].directionCosCutoff.xyz) > frame.lights[i].directionCosCutoff.w)) continue;
    float NdotL = dot(N, L);
    if (!(NdotL > 0.0)) continue;  // no diffuse and no specular where N·L ≤ 0
    vec3 Ip = frame.lights[i].intensity.rgb;
    float S = shadowFactor(i, P, N, L);
    I.diffuse += S * fAtt * (material.kd * NdotL * Ip);
    I.specular += S * fAtt * (material.ks * specularTerm(N, L, V, material.shininess, FACET_SPECULAR_MODEL) * Ip);
  }
  return I;
}

// I = O_d·diffuse + specular (linear, unclamped).
vec3 shade(Illumination illumination, vec3 baseColor) {
  return baseColor * illumination.diffuse + illumination.specular;
}

// V at P: toward the eye (perspective) or the constant -k (parallel).
vec3 viewVector(vec3 P) {
  return frame.eyePosition.w != 0.0 ? normalize(frame.eyePosition.xyz - P) : frame.towardEye.xyz;
}
