#pragma once
// The course's illumination equation on the CPU, written once for one pixel
// (F = float) or four, eight or sixteen at a time (F = Float4, Float8, Float16; lanes.h): the vertex stage of
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

#include "shading/environment.h"
#include "shading/lane_pairs.h"
#include "shading/lanes.h"
#include "shading/shading_math.h"
#include "shading/shadow_maps.h"
#include "shading/transform.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/light_frustum.h"

namespace facet {

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
// With `emissive` in k_e's place: 0 or k_e·E for a material with an emissive texture (texture.h, emissionAt).
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
  TowardLight<F> t;  // L set below on both branches (not zeroed first: 384 bytes a call at twice sixteen lanes)
  t.fAtt = F(1.0f), t.reaches = allLanes<F>();
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

// Where world point P reads one face of a light's shadow maps, on one lane or
// four: the map coordinates (u, v, z) after the divide by w, the bias =
// max(b_slope·(1 - N·L), b_min), and the texel (tx, ty) holding (u, v).
// `inside`: P is read (in front of the light's eye, not beyond its far
// plane); elsewhere P counts as lit and the other fields mean nothing.
template <class F>
struct ShadowCoordinates {
  MaskOf<F> inside;
  F u, v, z, bias;
  IntOf<F> tx, ty;
};
template <class F>
ShadowCoordinates<F> shadowCoordinates(const glm::mat4& shadowFromWorld, int size, const ShadowSettings& shadows, const Vec3Of<F>& P,
                                       const Vec3Of<F>& N, const Vec3Of<F>& L) {
  const glm::mat4& m = shadowFromWorld;
  // transformPoint (transform.h), one row at a time: ((m0·x + m1·y) + m2·z) + m3
  const auto row = [&](int r) { return ((F(m[0][r]) * P.x + F(m[1][r]) * P.y) + F(m[2][r]) * P.z) + F(m[3][r]); };
  const F sx = row(0), sy = row(1), sz = row(2), sw = row(3);
  ShadowCoordinates<F> at;
  at.u = sx / sw, at.v = sy / sw, at.z = sz / sw;
  at.inside = both(both(sw > F(0.0f), at.z <= F(1.0f)), both(at.u <= at.u, at.v <= at.v));  // x ≤ x: not NaN
  // Far outside the map every texel is outside too; the clamp (NaN to -1)
  // keeps the texel index an int without changing which texels a point inside reads.
  const F uc = select(at.u > F(-1.0f), select(at.u < F(2.0f), at.u, F(2.0f)), F(-1.0f));
  const F vc = select(at.v > F(-1.0f), select(at.v < F(2.0f), at.v, F(2.0f)), F(-1.0f));
  const F slope = F(shadows.biasSlope) * (F(1.0f) - dot3(N, L));
  at.bias = select(slope > F(shadows.biasMin), slope, F(shadows.biasMin));
  at.tx = truncateToInt(floorOf(uc * F(static_cast<float>(size))));
  at.ty = truncateToInt(floorOf(vc * F(static_cast<float>(size))));
  return at;
}

// Where world point P reads a light's shadow maps: the face, its layer, and
// shadowCoordinates there. `outside`: P counts as lit without a read.
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
  const ShadowCoordinates<float> c =
      shadowCoordinates<float>(light.shadowFromWorld[static_cast<std::size_t>(at.face)], maps.size, shadows, P, N, L);
  at.outside = !c.inside;
  at.u = c.u, at.v = c.v, at.z = c.z, at.bias = c.bias, at.tx = c.tx, at.ty = c.ty;
  return at;
}

// PCF's count: of the (2r+1)² texels of `layer` around (tx, ty), those not in
// shadow (!(zb > depth), zb = z - bias). Outside the map counts as lit; a
// point light's cube has no outside: a tap beyond its face's edge reads the edge texel.
inline int pcfLitCount(const ShadowMaps& maps, int layer, int tx, int ty, float zb, int r, bool cube) {
  const int size = maps.size;
  int lit = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const int x = cube ? std::clamp(tx + dx, 0, size - 1) : tx + dx, y = cube ? std::clamp(ty + dy, 0, size - 1) : ty + dy;
      if (x < 0 || y < 0 || x >= size || y >= size) ++lit;
      else if (!(zb > maps.texelFetch(layer, x, y))) ++lit;
    }
  return lit;
}

// S of one light at world point P: PCF over (2r+1)² texels of the light's
// map around shadowLookup's texel, a texel in shadow when z - bias > depth.
// Outside the map (or beyond its far plane) counts as lit.
inline float shadowFactor(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, glm::vec3 P, glm::vec3 N,
                          glm::vec3 L) {
  if (!light.hasShadowMap) return 1.0f;
  const ShadowLookup at = shadowLookup(maps, light, shadows, P, N, L);
  if (at.outside) return 1.0f;
  const int r = shadows.pcfRadius;
  const int lit = pcfLitCount(maps, at.layer, at.tx, at.ty, at.z - at.bias, r, light.light.kind == LightKind::Point);
  return static_cast<float>(lit) / static_cast<float>((2 * r + 1) * (2 * r + 1));
}

// shadowFactor for the lanes the light reaches (1 elsewhere; those lanes are dropped).
inline float shadowFactorLanes(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, glm::vec3 P, glm::vec3 N,
                               glm::vec3 L, bool) {
  return shadowFactor(maps, light, shadows, P, N, L);
}
#if defined(__SSE2__)
// pcfLitCount four texels of a row at a time, for a window wholly inside the
// map with room for its last four-texel load (pcfFitsRows says when).
inline int pcfLitCountRows(const ShadowMaps& maps, int layer, int tx, int ty, float zb, int r) {
  const __m128 z = _mm_set1_ps(zb);
  const float* texels = maps.layer(layer);
  const auto notShadowed = [&](const float* at) { return static_cast<unsigned>(_mm_movemask_ps(_mm_cmpngt_ps(z, _mm_loadu_ps(at)))); };  // !(zb > depth), NaN included
  if (r == 1) {  // the default 3x3 window: one load a row, the three rows' bits counted at once
    const float* row = texels + static_cast<std::size_t>(ty - 1) * static_cast<std::size_t>(maps.size) + (tx - 1);
    const std::size_t next = static_cast<std::size_t>(maps.size);
    return __builtin_popcount((notShadowed(row) | notShadowed(row + next) << 4 | notShadowed(row + 2 * next) << 8) & 0x777u);
  }
  int lit = 0;
  for (int y = ty - r; y <= ty + r; ++y) {
    const float* row = texels + static_cast<std::size_t>(y) * static_cast<std::size_t>(maps.size);
    for (int x = tx - r; x <= tx + r; x += 4) {
      const int n = std::min(4, tx + r + 1 - x);
      lit += __builtin_popcount(notShadowed(row + x) & ((1u << n) - 1u));
    }
  }
  return lit;
}
inline bool pcfFitsRows(int size, int tx, int ty, int r) {
  const int loads = (2 * r + 1 + 3) / 4;
  return tx - r >= 0 && tx - r + 4 * loads <= size && ty - r >= 0 && ty + r < size;
}

// cubeFace (pipeline/light_frustum.h) on lanes: the same comparisons, as selects.
template <class F>
IntOf<F> cubeFaceLanes(const Vec3Of<F>& d) {
  using I = IntOf<F>;
  const F ax = absOf(d.x), ay = absOf(d.y), az = absOf(d.z);
  const MaskOf<F> xMajor = both(ax >= ay, ax >= az), yMajor = ay >= az;
  const F zero(0.0f);
  return select(xMajor, select(d.x >= zero, I(0), I(1)), select(yMajor, select(d.y >= zero, I(2), I(3)), select(d.z >= zero, I(4), I(5))));
}

// Whether the active lanes (bits of `lanes`, one at least) read one face of
// the light's maps, and which: a point light's cube face of each lane's P
// (cubeFaceLanes), or a spot or directional light's one map.
template <class F>
bool oneFace(const FrameLight& light, const Vec3Of<F>& P, int lanes, int& face) {
  face = 0;
  if (light.light.kind != LightKind::Point) return true;
  const IntOf<F> faces = cubeFaceLanes<F>(P - splat<F>(light.light.position));
  alignas(64) std::int32_t each[kLaneCount<F>];
  storeLanes(each, faces);
  face = each[__builtin_ctz(static_cast<unsigned>(lanes))];  // the first active lane's
  return (lanes & ~laneBits(equalLanes(faces, IntOf<F>(face)))) == 0;
}

// S on F's lanes whose active lanes all read `face`: the coordinates on the
// lanes, then each lane's PCF window, its rows four texels at a time where
// they fit; the same reads and comparisons as shadowFactor, so the same S
// to the bit.
template <class F>
F shadowFactorOnFace(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, const Vec3Of<F>& P, const Vec3Of<F>& N,
                     const Vec3Of<F>& L, int lanes, int face) {
  constexpr int kLanes = kLaneCount<F>;
  const bool cube = light.light.kind == LightKind::Point;
  const int r = shadows.pcfRadius, size = maps.size;
  const float taps = static_cast<float>((2 * r + 1) * (2 * r + 1));
  const ShadowCoordinates<F> at = shadowCoordinates<F>(light.shadowFromWorld[static_cast<std::size_t>(face)], size, shadows, P, N, L);
  alignas(64) float zb[kLanes], lit[kLanes];
  alignas(64) std::int32_t tx[kLanes], ty[kLanes];
  storeLanes(zb, at.z - at.bias);
  storeLanes(tx, at.tx);
  storeLanes(ty, at.ty);
  const int read = lanes & laneBits(at.inside);
  const int layer = light.shadowLayer + face;
  for (int k = 0; k < kLanes; ++k) {
    lit[k] = taps;  // not read: S = taps / taps = 1
    if (read & (1 << k))
      lit[k] = static_cast<float>(pcfFitsRows(size, tx[k], ty[k], r) ? pcfLitCountRows(maps, layer, tx[k], ty[k], zb[k], r)
                                                                     : pcfLitCount(maps, layer, tx[k], ty[k], zb[k], r, cube));
  }
  F count;
  loadLanes(count, lit);
  return count / F(taps);  // shadowFactor's lit / taps, every lane's division at once
}

// Four lanes: where the active lanes read one face, shadowFactorOnFace;
// else each active lane alone (shadowFactor).
inline Float4 shadowFactorLanes(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, const Vec3x4& P, const Vec3x4& N,
                                const Vec3x4& L, Mask4 active) {
  const int lanes = laneBits(active);
  if (!light.hasShadowMap || lanes == 0) return Float4(1.0f);
  int face = 0;
  if (oneFace<Float4>(light, P, lanes, face)) return shadowFactorOnFace<Float4>(maps, light, shadows, P, N, L, lanes, face);
  alignas(16) float S[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  alignas(16) float p[3][4], n[3][4], l[3][4];
  _mm_store_ps(p[0], P.x.v), _mm_store_ps(p[1], P.y.v), _mm_store_ps(p[2], P.z.v);
  _mm_store_ps(n[0], N.x.v), _mm_store_ps(n[1], N.y.v), _mm_store_ps(n[2], N.z.v);
  _mm_store_ps(l[0], L.x.v), _mm_store_ps(l[1], L.y.v), _mm_store_ps(l[2], L.z.v);
  for (int k = 0; k < 4; ++k)
    if (lanes & (1 << k))
      S[k] = shadowFactor(maps, light, shadows, {p[0][k], p[1][k], p[2][k]}, {n[0][k], n[1][k], n[2][k]}, {l[0][k], l[1][k], l[2][k]});
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
#if defined(__AVX2__)
// Eight or sixteen lanes: where the active lanes read one face,
// shadowFactorOnFace on all of them (one projection); else the look-ups of
// half the width on each half.
template <class F>
F shadowFactorWide(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, const Vec3Of<F>& P, const Vec3Of<F>& N,
                   const Vec3Of<F>& L, MaskOf<F> active) {
  const int lanes = laneBits(active);
  if (!light.hasShadowMap || lanes == 0) return F(1.0f);
  int face = 0;
  if (oneFace<F>(light, P, lanes, face)) return shadowFactorOnFace<F>(maps, light, shadows, P, N, L, lanes, face);
  using Half = decltype(halfOf(F(), 0));
  Half S[2];
  for (int h = 0; h < 2; ++h)
    S[h] = anyLane(halfOf(active, h)) ? shadowFactorLanes(maps, light, shadows, halfOf(P, h), halfOf(N, h), halfOf(L, h), halfOf(active, h)) : Half(1.0f);
  return joined(S[0], S[1]);
}
// env(R) on each half.
template <class Vec3>
Vec3 environmentWide(const EnvironmentMap& map, const Vec3& R) {
  return joined(environmentLanes(map, halfOf(R, 0)), environmentLanes(map, halfOf(R, 1)));
}
inline Float8 shadowFactorLanes(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, const Vec3x8& P, const Vec3x8& N,
                                const Vec3x8& L, Mask8 active) {
  return shadowFactorWide<Float8>(maps, light, shadows, P, N, L, active);
}
inline Vec3x8 environmentLanes(const EnvironmentMap& map, const Vec3x8& R) { return environmentWide(map, R); }
#endif
#if defined(__AVX512F__)
inline Float16 shadowFactorLanes(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, const Vec3x16& P, const Vec3x16& N,
                                 const Vec3x16& L, Mask16 active) {
  return shadowFactorWide<Float16>(maps, light, shadows, P, N, L, active);
}
inline Vec3x16 environmentLanes(const EnvironmentMap& map, const Vec3x16& R) { return environmentWide(map, R); }
#endif

#if defined(__SSE2__)
// Twice a lane type (lane_pairs.h): where the active lanes read one face,
// shadowFactorOnFace on all of them; else each half's look-ups in turn.
template <class F>
Twice<F> shadowFactorLanes(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, const TwiceVec3<F>& P,
                           const TwiceVec3<F>& N, const TwiceVec3<F>& L, const Twice<MaskOf<F>>& active) {
  const int lanes = laneBits(active);
  if (!light.hasShadowMap || lanes == 0) return Twice<F>(1.0f);
  int face = 0;
  if (oneFace<Twice<F>>(light, P, lanes, face)) return shadowFactorOnFace<Twice<F>>(maps, light, shadows, P, N, L, lanes, face);
  const auto half = [&](int h, const MaskOf<F>& on) {
    return anyLane(on) ? shadowFactorLanes(maps, light, shadows, P.half(h), N.half(h), L.half(h), on) : F(1.0f);
  };
  return {half(0, active.a), half(1, active.b)};
}
// env(R) on each half.
template <class F>
TwiceVec3<F> environmentLanes(const EnvironmentMap& map, const TwiceVec3<F>& R) {
  return joinedTwice<F>(environmentLanes(map, R.half(0)), environmentLanes(map, R.half(1)));
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
  // Environment mapping: the course's k_r·I_r, I_r = env(R), R = 2(N·V)N - V, joins the highlights (PIPELINE.md, "Textures").
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

}  // namespace facet
