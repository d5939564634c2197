// The course's illumination equation in GLSL.
// Mirror: renderer/shading/lighting.h — the same functions, in the same order,
// with the same names, arguments and float operations (shading_math.glsl).
// Change one, change the other.
//
//   I = k_e + k_a·I_a·O_d + Σ_lights S·f_att·(k_d·I_p·max(N·L, 0)·O_d + k_s·I_p·spec·O_s)
//   O_s = (1 - m) + m·O_d   (the specular colour: the light's for a dielectric, tinted for a metal)
//
// Needs frame_block.glsl, transform.glsl, shading_math.glsl and
// `uniform sampler2DArray shadowMaps;` (draw_uniforms.glsl) before it, and
// the program's specialization macros (renderer/gl/shader_variant.cpp):
// FACET_LIGHT_COUNT, FACET_LIGHT_KIND(i), FACET_LIGHT_SHADOWED(i),
// FACET_SPECULAR_MODEL, FACET_PCF_RADIUS. Compiled in, the branches that do
// not apply to this frame are gone (llvmpipe runs both sides of a branch).

// f_att = min(1, 1/(c1 + c2·d + c3·d²)), as ((c1 + c2·d) + (c3·d)·d)
float attenuation(vec3 c, float d) {
  precise float r = minOne(1.0 / ((c.x + c.y * d) + (c.z * d) * d));
  return r;
}

// The unit vector L from P toward light i, f_att at P, and whether a spot's
// cone reaches P (always for other kinds): the part of a light's term every
// shading mode shares.
struct TowardLight {
  vec3 L;
  float fAtt;
  bool reaches;
};
TowardLight towardLight(int i, vec3 P) {
  int kind = FACET_LIGHT_KIND(i);
  precise vec3 L;
  precise float fAtt = 1.0;
  if (kind == kLightDirectional) {
    L = -frame.lights[i].directionCosCutoff.xyz;
  } else {
    precise vec3 toLight = frame.lights[i].position.xyz - P;
    precise float d = length3(toLight);
    L = toLight / d;
    fAtt = attenuation(frame.lights[i].attenuation.xyz, d);
  }
  bool reaches = kind != kLightSpot || dot3(-L, frame.lights[i].directionCosCutoff.xyz) > frame.lights[i].directionCosCutoff.w;
  return TowardLight(L, fAtt, reaches);
}

// spec = max(R·V, 0)^n (Phong) or max(N·H, 0)^n (Blinn-Phong).
float specularTerm(vec3 N, vec3 L, vec3 V, float shininess, int model) {
  if (model == 0) {
    precise vec3 R = (2.0 * dot3(L, N)) * N - L;
    return power(maxZero(dot3(R, V)), shininess);
  }
  precise vec3 H = normalize3(L + V);
  return power(maxZero(dot3(N, H)), shininess);
}

// A texel index beyond a map's edge (a spot or directional map counts such a tap lit).
bool outsideMap(int xi, int yi, int size) {
  return xi < 0 || yi < 0 || xi >= size || yi >= size;
}

// S of light i at P: PCF over (2r+1)² texels read with texelFetch; in shadow
// when z - bias > depth, bias = max(b_slope·(1 - N·L), b_min); outside the
// map or beyond its far plane counts as lit.
float shadowFactor(int i, vec3 P, vec3 N, vec3 L) {
  if (!FACET_LIGHT_SHADOWED(i)) return 1.0;
  int face = FACET_LIGHT_KIND(i) == kLightPoint ? cubeFace(P - frame.lights[i].position.xyz) : 0;
  precise vec4 s = transformPoint(frame.lights[i].shadowFromWorld[face], P);
  if (!(s.w > 0.0)) return 1.0;
  precise float u = s.x / s.w, v = s.y / s.w, z = s.z / s.w;
  if (!(z <= 1.0) || isnan(u) || isnan(v)) return 1.0;
  // Far outside the map every texel is outside too; the clamp keeps the texel
  // index an int without changing which texels a point inside reads.
  float uc = u < -1.0 ? -1.0 : (u > 2.0 ? 2.0 : u);
  float vc = v < -1.0 ? -1.0 : (v > 2.0 ? 2.0 : v);
  precise float slope = frame.shadowParams.x * (1.0 - dot3(N, L));
  float bias = slope > frame.shadowParams.y ? slope : frame.shadowParams.y;
  int size = int(frame.shadowParams.z), r = FACET_PCF_RADIUS;
  precise float x = uc * float(size), y = vc * float(size);
  int tx = int(floor(x));
  int ty = int(floor(y));
  int layer = frame.lights[i].shadow.x + face;
  // A point light's cube has no outside: a tap beyond its face's edge reads the edge texel.
  bool cube = FACET_LIGHT_KIND(i) == kLightPoint;
  precise float compared = z - bias;
  int lit = 0;
#if FACET_PCF_RADIUS == 1
  // The 3×3 window in four gathers of 2×2 texels, {tx - 1, tx} and {tx + 1, tx + 2}
  // each way (column and row tx + 2 unread): a gather at the corner tx / size
  // reads texels tx - 1 and tx (floor(tx - 0.5)), with half a texel to spare for
  // the division's rounding. Past an edge it reads the edge texel (clamp to
  // edge): a cube face's rule; a spot or directional map counts the tap lit.
  for (int gy = 0; gy < 2; ++gy)
    for (int gx = 0; gx < 2; ++gx) {
      int x0 = tx - 1 + 2 * gx, y0 = ty - 1 + 2 * gy;  // the gather's lower-left texel
      vec4 t = textureGather(shadowMaps, vec3(float(x0 + 1) / float(size), float(y0 + 1) / float(size), float(layer)), 0);
      // textureGather's order: (x0, y0 + 1), (x0 + 1, y0 + 1), (x0 + 1, y0), (x0, y0)
      float depths[4] = float[4](t.w, t.z, t.x, t.y);
      for (int k = 0; k < 4; ++k) {
        int xi = x0 + (k & 1), yi = y0 + (k >> 1);
        bool inWindow = xi <= tx + 1 && yi <= ty + 1;
        if (inWindow && ((!cube && outsideMap(xi, yi, size)) || !(compared > depths[k]))) ++lit;
      }
    }
#else
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      int xi = cube ? clamp(tx + dx, 0, size - 1) : tx + dx, yi = cube ? clamp(ty + dy, 0, size - 1) : ty + dy;
      if (outsideMap(xi, yi, size)) ++lit;
      else if (!(compared > texelFetch(shadowMaps, ivec3(xi, yi, layer), 0).r)) ++lit;
    }
#endif
  precise float S = float(lit) / float((2 * r + 1) * (2 * r + 1));
  return S;
}

// I split in the part O_d multiplies and the rest (Gouraud and flat apply a
// textured O_d per pixel). With H = Σ S·f_att·k_s·I_p·spec,
// O_s·H = (1 - m)·H + m·O_d·H, so  I = O_d·diffuse + specular
//   diffuse  = (k_a·I_a + Σ S·f_att·k_d·I_p·max(N·L, 0)) + m·H
//   specular = k_e + (1 - m)·H
struct Illumination {
  vec3 diffuse;
  vec3 specular;
};

// Illumination at world point P with unit normal N and unit view vector V.
Illumination illuminate(CourseMaterial material, vec3 P, vec3 N, vec3 V) {
  precise float ambient = material.ka * frame.ambient.x;
  precise vec3 diffuse = vec3(ambient, ambient, ambient);
  precise vec3 highlights = vec3(0.0, 0.0, 0.0);  // H
  // A light that adds nothing is skipped by an if, never a continue: llvmpipe
  // gave this loop with continues slower code (tests/gl/test_shader_source.cpp).
  for (int i = 0; i < FACET_LIGHT_COUNT; ++i) {
    TowardLight toward = towardLight(i, P);
    vec3 L = toward.L;
    float fAtt = toward.fAtt;
    precise float NdotL = dot3(N, L);
    if (toward.reaches && NdotL > 0.0) {  // no diffuse and no specular where N·L ≤ 0
      vec3 Ip = frame.lights[i].intensity.rgb;
      precise float S = shadowFactor(i, P, N, L);
      precise float lightFactor = S * fAtt;
      precise vec3 addDiffuse = lightFactor * ((material.kd * NdotL) * Ip);
      precise vec3 addSpecular = lightFactor * ((material.ks * specularTerm(N, L, V, material.shininess, FACET_SPECULAR_MODEL)) * Ip);
      diffuse = diffuse + addDiffuse;
      highlights = highlights + addSpecular;
    }
  }
#if defined(FACET_ENVIRONMENT) && FACET_ENVIRONMENT
  // Environment mapping: the course's k_r·I_r, I_r = env(R), R = 2(N·V)N - V, joins the highlights (PIPELINE.md, "Textures").
  precise vec3 R = (2.0 * dot3(N, V)) * N - V;
  highlights = highlights + frame.environment.x * environmentAt(R, 0);
#endif
  precise vec3 tinted = diffuse + material.metallic * highlights;
  precise vec3 specular = material.emissive + (1.0 - material.metallic) * highlights;
  return Illumination(tinted, specular);
}

// I = O_d·diffuse + specular (linear, unclamped).
vec3 shade(Illumination illumination, vec3 baseColor) {
  precise vec3 r = baseColor * illumination.diffuse + illumination.specular;
  return r;
}

// V at P: toward the eye (perspective) or the constant -k (parallel).
vec3 viewVector(vec3 P) {
  return frame.eyePosition.w != 0.0 ? normalize3(frame.eyePosition.xyz - P) : frame.towardEye.xyz;
}
