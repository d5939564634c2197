#pragma once
// The course's illumination equation on the CPU, written once for one pixel
// (F = float) or four at a time (F = Float4, lanes.h): the vertex stage of
// Gouraud, flat shading's triangles and Phong's pixels all call it.
// Mirror: shaders/lighting.glsl, the same functions in the same order with
// the same names, arguments and float operations. Change one, change the other.
//
//   I = k_e + k_a·I_a·O_d + Σ_lights S·f_att·(k_d·I_p·max(N·L, 0)·O_d + k_s·I_p·spec·O_s)
//   O_s = (1 - m) + m·O_d   (the specular colour: the light's for a dielectric, tinted for a metal)
//
// Lanes: a light that does not reach a lane (spot cut-off, N·L ≤ 0) leaves
// that lane's sums as they were (a select), which is what the one-pixel code
// does when it skips the light.
#include <algorithm>
#include <cstdint>

#include <glm/vec3.hpp>

#include "cpu/environment_mapping.h"
#include "cpu/lanes.h"
#include "cpu/shading_math.h"
#include "cpu/shadow_maps.h"
#include "cpu/vertex_math.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/light_frustum.h"

namespace facet::cpu {

// I split in the part O_d multiplies and the rest, so that a textured O_d can
// be applied per pixel when lighting is per vertex (Gouraud) or per triangle (flat).
// With H = Σ S·f_att·k_s·I_p·spec, O_s·H = (1 - m)·H + m·O_d·H, so
//   I = O_d·diffuse + specular
//   diffuse  = (k_a·I_a + Σ S·f_att·k_d·I_p·max(N·L, 0)) + m·H
//   specular = k_e + (1 - m)·H
template <class F>
struct IlluminationOf {
  Vec3Of<F> diffuse{}, specular{};
};
using Illumination = IlluminationOf<float>;

// The course coefficients of the material shaded in each lane.
template <class F>
struct LaneMaterial {
  Vec3Of<F> emissive;  // k_e
  F ka, kd, ks, shininess, metallic;
};
// With `emissive` in k_e's place: 0 or k_e·E for a material with an emissive texture (texture_sampling.h, emissionAt).
inline LaneMaterial<float> laneMaterial(const CourseMaterial& m, glm::vec3 emissive) { return {emissive, m.ka, m.kd, m.ks, m.shininess, m.metallic}; }
inline LaneMaterial<float> laneMaterial(const CourseMaterial& m) { return laneMaterial(m, m.emissive); }

// f_att = min(1, 1/(c1 + c2·d + c3·d²)), as ((c1 + c2·d) + (c3·d)·d)
template <class F>
F attenuation(glm::vec3 c, F d) {
  return minOne(F(1.0f) / ((F(c.x) + F(c.y) * d) + (F(c.z) * d) * d));
}

// The unit vector L from P toward a light, f_att at P, and whether a spot's
// cone reaches P (every lane for other kinds): the part of a light's term
// every shading mode shares.
template <class F>
struct TowardLight {
  Vec3Of<F> L;
  F fAtt;
  MaskOf<F> reaches;
};
template <class F>
MaskOf<F> allLanes() {
  return F(0.0f) <= F(0.0f);
}
template <class F>
TowardLight<F> towardLight(const FrameLight& fl, const Vec3Of<F>& P) {
  const Light& light = fl.light;
  TowardLight<F> t{Vec3Of<F>(), F(1.0f), allLanes<F>()};
  if (light.kind == LightKind::Directional) {
    t.L = splat<F>(-light.direction);
  } else {
    const Vec3Of<F> toLight = splat<F>(light.position) - P;
    const F d = length3(toLight);
    t.L = toLight / d;
    t.fAtt = attenuation(light.attenuation, d);
  }
  if (light.kind == LightKind::Spot) t.reaches = dot3(-t.L, splat<F>(light.direction)) > F(fl.cosCutoff);
  return t;
}

// spec = max(R·V, 0)^n with R = 2(L·N)N - L (Phong), or max(N·H, 0)^n with
// H = normalize(L + V) (Blinn-Phong). The caller drops it where N·L ≤ 0.
template <class F>
F specularTerm(const Vec3Of<F>& N, const Vec3Of<F>& L, const Vec3Of<F>& V, F shininess, SpecularModel model) {
  if (model == SpecularModel::Phong) {
    const Vec3Of<F> R = (F(2.0f) * dot3(L, N)) * N - L;
    return power(maxZero(dot3(R, V)), shininess);
  }
  const Vec3Of<F> H = normalize3(L + V);
  return power(maxZero(dot3(N, H)), shininess);
}

// Where world point P reads a light's shadow maps: the face, the map
// coordinates (u, v, z) after the divide by w, the texel (tx, ty) holding
// (u, v), and the bias = max(b_slope·(1 - N·L), b_min). `outside`: P counts
// as lit without a read (behind the light's eye, beyond its far plane).
struct ShadowLookup {
  bool outside = true;
  int face = 0, layer = 0;
  float u = 0, v = 0, z = 0, bias = 0;
  int tx = 0, ty = 0;
};
inline ShadowLookup shadowLookup(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, glm::vec3 P, glm::vec3 N,
                                 glm::vec3 L) {
  ShadowLookup at;
  at.face = light.light.kind == LightKind::Point ? cubeFace(P - light.light.position) : 0;
  at.layer = light.shadowLayer + at.face;
  const glm::vec4 s = transformPoint(light.shadowFromWorld[static_cast<std::size_t>(at.face)], P);
  if (!(s.w > 0.0f)) return at;
  at.u = s.x / s.w, at.v = s.y / s.w, at.z = s.z / s.w;
  if (!(at.z <= 1.0f) || std::isnan(at.u) || std::isnan(at.v)) return at;
  at.outside = false;
  // Far outside the map every texel is outside too; the clamp keeps the texel
  // index an int without changing which texels a point inside reads.
  const float uc = at.u < -1.0f ? -1.0f : (at.u > 2.0f ? 2.0f : at.u);
  const float vc = at.v < -1.0f ? -1.0f : (at.v > 2.0f ? 2.0f : at.v);
  const float slope = shadows.biasSlope * (1.0f - dot3(N, L));
  at.bias = slope > shadows.biasMin ? slope : shadows.biasMin;
  at.tx = static_cast<int>(std::floor(uc * static_cast<float>(maps.size)));
  at.ty = static_cast<int>(std::floor(vc * static_cast<float>(maps.size)));
  return at;
}

// S of one light at world point P: PCF over (2r+1)² texels of the light's
// map around shadowLookup's texel, a texel in shadow when z - bias > depth.
// Outside the map (or beyond its far plane) counts as lit. A point light's
// cube has no outside: a tap beyond its face's edge reads the edge texel.
// One pixel at a time: texel reads do not go into lanes.
inline float shadowFactor(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, glm::vec3 P, glm::vec3 N,
                          glm::vec3 L) {
  if (!light.hasShadowMap) return 1.0f;
  const ShadowLookup at = shadowLookup(maps, light, shadows, P, N, L);
  if (at.outside) return 1.0f;
  const int size = maps.size, r = shadows.pcfRadius;
  const bool cube = light.light.kind == LightKind::Point;
  int lit = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const int x = cube ? std::clamp(at.tx + dx, 0, size - 1) : at.tx + dx, y = cube ? std::clamp(at.ty + dy, 0, size - 1) : at.ty + dy;
      if (x < 0 || y < 0 || x >= size || y >= size) ++lit;
      else if (!(at.z - at.bias > maps.texelFetch(at.layer, x, y))) ++lit;
    }
  return static_cast<float>(lit) / static_cast<float>((2 * r + 1) * (2 * r + 1));
}

// shadowFactor for the lanes the light reaches (1 elsewhere; those lanes are dropped).
inline float shadowFactorLanes(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, glm::vec3 P, glm::vec3 N,
                               glm::vec3 L, bool) {
  return shadowFactor(maps, light, shadows, P, N, L);
}
#if defined(__SSE2__)
inline Float4 shadowFactorLanes(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, const Vec3x4& P, const Vec3x4& N,
                                const Vec3x4& L, Mask4 active) {
  if (!light.hasShadowMap) return Float4(1.0f);
  alignas(16) float p[3][4], n[3][4], l[3][4], S[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  const Vec3x4* from[3] = {&P, &N, &L};
  float (*to[3])[4] = {p, n, l};
  for (int v = 0; v < 3; ++v) {
    _mm_store_ps(to[v][0], from[v]->x.v);
    _mm_store_ps(to[v][1], from[v]->y.v);
    _mm_store_ps(to[v][2], from[v]->z.v);
  }
  const int lanes = laneBits(active);
  for (int k = 0; k < 4; ++k)
    if (lanes & (1 << k)) S[k] = shadowFactor(maps, light, shadows, {p[0][k], p[1][k], p[2][k]}, {n[0][k], n[1][k], n[2][k]}, {l[0][k], l[1][k], l[2][k]});
  return Float4(_mm_load_ps(S));
}
#endif

// env(R) for one lane or four (the map is read one pixel at a time, as shadow maps are).
inline glm::vec3 environmentLanes(const EnvironmentMap& map, glm::vec3 R) { return environmentAt(map, R, 0); }
#if defined(__SSE2__)
inline Vec3x4 environmentLanes(const EnvironmentMap& map, const Vec3x4& R) {
  alignas(16) float r[3][4], out[3][4];
  _mm_store_ps(r[0], R.x.v);
  _mm_store_ps(r[1], R.y.v);
  _mm_store_ps(r[2], R.z.v);
  for (int k = 0; k < 4; ++k) {
    const glm::vec3 c = environmentAt(map, {r[0][k], r[1][k], r[2][k]}, 0);
    out[0][k] = c.x, out[1][k] = c.y, out[2][k] = c.z;
  }
  return Vec3x4(Float4(_mm_load_ps(out[0])), Float4(_mm_load_ps(out[1])), Float4(_mm_load_ps(out[2])));
}
#endif

// Illumination at world point P with unit normal N and unit view vector V.
// S of each light from `shadows`: the light's shadow maps (ShadowMaps, the
// rasterizers' pass 1), or whatever type has its own shadowFactorLanes (the
// ray tracer's shadow rays, found by argument-dependent lookup).
template <class F, class Shadows>
IlluminationOf<F> illuminate(const FrameInputs& frame, const Shadows& shadows, const LaneMaterial<F>& material, const Vec3Of<F>& P,
                             const Vec3Of<F>& N, const Vec3Of<F>& V) {
  using Vec3 = Vec3Of<F>;
  IlluminationOf<F> I;
  const F ambient = material.ka * F(frame.ambient);
  I.diffuse = Vec3(ambient, ambient, ambient);
  Vec3 highlights(F(0.0f), F(0.0f), F(0.0f));  // H
  for (const FrameLight& fl : frame.lights) {
    const TowardLight<F> toward = towardLight<F>(fl, P);
    const Vec3& L = toward.L;
    const F fAtt = toward.fAtt;
    const F NdotL = dot3(N, L);
    const MaskOf<F> active = both(toward.reaches, NdotL > F(0.0f));  // no diffuse and no specular where N·L ≤ 0
    if (!anyLane(active)) continue;
    const Vec3 Ip = splat<F>(fl.intensity);
    const F S = shadowFactorLanes(shadows, fl, frame.shadows, P, N, L, active);
    const Vec3 diffuse = (S * fAtt) * ((material.kd * NdotL) * Ip);
    const Vec3 specular = (S * fAtt) * ((material.ks * specularTerm(N, L, V, material.shininess, frame.specular)) * Ip);
    I.diffuse = select(active, I.diffuse + diffuse, I.diffuse);
    highlights = select(active, highlights + specular, highlights);
  }
  // Environment mapping: the course's k_r·I_r, I_r = env(R), R = 2(N·V)N - V, joins the highlights (PIPELINE.md, section 8).
  if (frame.environment.map) {
    const Vec3 R = (F(2.0f) * dot3(N, V)) * N - V;
    highlights = highlights + F(frame.environment.reflectivity) * environmentLanes(*frame.environment.map, R);
  }
  I.diffuse = I.diffuse + material.metallic * highlights;
  I.specular = material.emissive + (F(1.0f) - material.metallic) * highlights;
  return I;
}

// I = O_d·diffuse + specular (linear, unclamped).
template <class F>
Vec3Of<F> shade(const IlluminationOf<F>& illumination, const Vec3Of<F>& baseColor) {
  return baseColor * illumination.diffuse + illumination.specular;
}

// V at P: toward the eye (perspective) or the constant -k (parallel).
template <class F>
Vec3Of<F> viewVector(const FrameInputs& frame, const Vec3Of<F>& P) {
  return frame.perspective ? normalize3(splat<F>(frame.eyePosition) - P) : splat<F>(frame.towardEye);
}

}  // namespace facet::cpu
