#include "cpu/phong_batch.h"

#include <cmath>

#include "cpu/srgb_table.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace facet::cpu {

#if defined(__SSE2__)
namespace {

// Four lanes of a vec3.
struct Vec3x4 {
  __m128 x, y, z;
};

__m128 splat(float v) { return _mm_set1_ps(v); }
Vec3x4 splat(glm::vec3 v) { return {splat(v.x), splat(v.y), splat(v.z)}; }
Vec3x4 load(const float (&v)[3][PhongBatch::kLanes]) { return {_mm_load_ps(v[0]), _mm_load_ps(v[1]), _mm_load_ps(v[2])}; }
Vec3x4 sub(Vec3x4 a, Vec3x4 b) { return {_mm_sub_ps(a.x, b.x), _mm_sub_ps(a.y, b.y), _mm_sub_ps(a.z, b.z)}; }
Vec3x4 plus(Vec3x4 a, Vec3x4 b) { return {_mm_add_ps(a.x, b.x), _mm_add_ps(a.y, b.y), _mm_add_ps(a.z, b.z)}; }
// s·v (glm's scalar * vec3: each component times s)
Vec3x4 scale(__m128 s, Vec3x4 v) { return {_mm_mul_ps(s, v.x), _mm_mul_ps(s, v.y), _mm_mul_ps(s, v.z)}; }
// glm::dot: (a.x·b.x + a.y·b.y) + a.z·b.z
__m128 dot(Vec3x4 a, Vec3x4 b) { return _mm_add_ps(_mm_add_ps(_mm_mul_ps(a.x, b.x), _mm_mul_ps(a.y, b.y)), _mm_mul_ps(a.z, b.z)); }
// glm::normalize: v · (1 / sqrt(v·v))
Vec3x4 normalize(Vec3x4 v) { return scale(_mm_div_ps(splat(1.0f), _mm_sqrt_ps(dot(v, v))), v); }
// mask ? a : b
__m128 select(__m128 mask, __m128 a, __m128 b) { return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b)); }
Vec3x4 select(__m128 mask, Vec3x4 a, Vec3x4 b) { return {select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z)}; }
// std::max(a, 0.0f) = (a < 0) ? 0 : a (NaN stays NaN, as in the scalar code)
__m128 maxZero(__m128 a) { return _mm_andnot_ps(_mm_cmplt_ps(a, _mm_setzero_ps()), a); }

}  // namespace

void PhongBatch::flush() {
  if (count_ == 0) return;
  for (int k = count_; k < kLanes; ++k) {  // unused lanes repeat lane 0; their results are dropped
    for (int c = 0; c < 3; ++c) P_[c][k] = P_[c][0], N_[c][k] = N_[c][0], O_[c][k] = O_[c][0];
    back_[k] = back_[0];
    material_[k] = material_[0];
  }
  for (int k = 0; k < kLanes; ++k) {
    const CourseMaterial& m = *material_[k];
    for (int c = 0; c < 3; ++c) E_[c][k] = m.emissive[c];
    ka_[k] = m.ka, kd_[k] = m.kd, ks_[k] = m.ks, n_[k] = m.shininess;
  }
  const Vec3x4 P = load(P_);
  // N = normalize(interpolated N), then -N on a back face (two-sided lighting)
  const Vec3x4 unit = normalize(load(N_));
  const __m128 flip = _mm_load_ps(back_);
  const Vec3x4 N{_mm_xor_ps(unit.x, flip), _mm_xor_ps(unit.y, flip), _mm_xor_ps(unit.z, flip)};
  // viewVector
  const Vec3x4 V = frame_.perspective ? normalize(sub(splat(frame_.eyePosition), P)) : splat(frame_.towardEye);
  // illuminate
  const __m128 ambient = _mm_mul_ps(_mm_load_ps(ka_), splat(frame_.ambient));
  Vec3x4 diffuse{ambient, ambient, ambient};
  Vec3x4 specular = load(E_);
  const __m128 kd = _mm_load_ps(kd_), ks = _mm_load_ps(ks_), one = splat(1.0f);
  for (const FrameLight& fl : frame_.lights) {
    const Light& light = fl.light;
    Vec3x4 L;
    __m128 fAtt = one;
    if (light.kind == LightKind::Directional) {
      L = splat(-light.direction);
    } else {
      const Vec3x4 toLight = sub(splat(light.position), P);
      const __m128 d = _mm_sqrt_ps(dot(toLight, toLight));
      L = {_mm_div_ps(toLight.x, d), _mm_div_ps(toLight.y, d), _mm_div_ps(toLight.z, d)};
      // attenuation: min(1, 1/((c1 + c2·d) + (c3·d)·d)); minps(x, 1) is (x < 1) ? x : 1, as std::min(1.0f, x)
      const glm::vec3 c = light.attenuation;
      const __m128 denominator = _mm_add_ps(_mm_add_ps(splat(c.x), _mm_mul_ps(splat(c.y), d)), _mm_mul_ps(_mm_mul_ps(splat(c.z), d), d));
      fAtt = _mm_min_ps(_mm_div_ps(one, denominator), one);
    }
    __m128 active = _mm_cmpeq_ps(one, one);
    if (light.kind == LightKind::Spot) {
      const __m128 sign = splat(-0.0f);  // -L: the sign bit flipped, exactly as glm's unary minus
      const Vec3x4 minusL{_mm_xor_ps(L.x, sign), _mm_xor_ps(L.y, sign), _mm_xor_ps(L.z, sign)};
      active = _mm_cmpgt_ps(dot(minusL, splat(light.direction)), splat(fl.cosCutoff));
    }
    const __m128 NdotL = dot(N, L);
    active = _mm_and_ps(active, _mm_cmpgt_ps(NdotL, _mm_setzero_ps()));
    const int activeLanes = _mm_movemask_ps(active);
    if (activeLanes == 0) continue;

    const glm::vec3 Ip = light.color * light.intensity;
    // S per lane (texel reads); only lanes the light reaches, as in the scalar loop.
    alignas(16) float S[kLanes] = {1.0f, 1.0f, 1.0f, 1.0f};
    if (fl.hasShadowMap) {
      alignas(16) float l[3][kLanes], n[3][kLanes];
      _mm_store_ps(n[0], N.x);
      _mm_store_ps(n[1], N.y);
      _mm_store_ps(n[2], N.z);
      _mm_store_ps(l[0], L.x);
      _mm_store_ps(l[1], L.y);
      _mm_store_ps(l[2], L.z);
      for (int k = 0; k < count_; ++k)
        if (activeLanes & (1 << k))
          S[k] = shadowFactor(maps_, fl, frame_.shadows, {P_[0][k], P_[1][k], P_[2][k]}, {n[0][k], n[1][k], n[2][k]}, {l[0][k], l[1][k], l[2][k]});
    }
    // specularTerm's base, then pow per lane
    __m128 base;
    if (frame_.specular == SpecularModel::Phong) {
      const Vec3x4 R = sub(scale(_mm_mul_ps(splat(2.0f), dot(L, N)), N), L);
      base = maxZero(dot(R, V));
    } else {
      base = maxZero(dot(N, normalize(plus(L, V))));
    }
    alignas(16) float b[kLanes], spec[kLanes] = {0.0f, 0.0f, 0.0f, 0.0f};
    _mm_store_ps(b, base);
    for (int k = 0; k < count_; ++k)
      if (activeLanes & (1 << k)) spec[k] = std::pow(b[k], n_[k]);
    // S·f_att·(k_d·(N·L)·I_p) and S·f_att·(k_s·spec·I_p), added where the light reaches
    const __m128 sf = _mm_mul_ps(_mm_load_ps(S), fAtt);
    const __m128 kdN = _mm_mul_ps(kd, NdotL), ksSpec = _mm_mul_ps(ks, _mm_load_ps(spec));
    const Vec3x4 IpX = splat(Ip);
    const Vec3x4 addDiffuse = scale(sf, scale(kdN, IpX));
    const Vec3x4 addSpecular = scale(sf, scale(ksSpec, IpX));
    diffuse = select(active, plus(diffuse, addDiffuse), diffuse);
    specular = select(active, plus(specular, addSpecular), specular);
  }
  // shade: O_d·diffuse + specular
  const Vec3x4 O = load(O_);
  const Vec3x4 color{_mm_add_ps(_mm_mul_ps(O.x, diffuse.x), specular.x), _mm_add_ps(_mm_mul_ps(O.y, diffuse.y), specular.y),
                     _mm_add_ps(_mm_mul_ps(O.z, diffuse.z), specular.z)};
  alignas(16) float rgb[3][kLanes];
  _mm_store_ps(rgb[0], color.x);
  _mm_store_ps(rgb[1], color.y);
  _mm_store_ps(rgb[2], color.z);
  std::uint8_t bytes[3][kLanes];
  for (int c = 0; c < 3; ++c) srgb_.encode4(rgb[c], bytes[c]);
  for (int k = 0; k < count_; ++k) pixels_[offset_[k]] = {bytes[0][k], bytes[1][k], bytes[2][k], 255};
  count_ = 0;
}

#else

void PhongBatch::flush() {
  for (int k = 0; k < count_; ++k) {
    const glm::vec3 P{P_[0][k], P_[1][k], P_[2][k]};
    glm::vec3 N = glm::normalize(glm::vec3{N_[0][k], N_[1][k], N_[2][k]});
    if (std::signbit(back_[k])) N = -N;
    const glm::vec3 O{O_[0][k], O_[1][k], O_[2][k]};
    pixels_[offset_[k]] = srgb_.pixel(shade(illuminate(frame_, maps_, *material_[k], P, N, viewVector(frame_, P)), O));
  }
  count_ = 0;
}

#endif

}  // namespace facet::cpu
