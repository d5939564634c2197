#include "cpu/phong_batch.h"

#include <cmath>

#include "cpu/fog.h"
#include "cpu/blending.h"

namespace facet::cpu {

#if defined(__SSE2__)
namespace {

Vec3x4 load(const float (&v)[3][PhongBatch::kLanes]) {
  return {Float4(_mm_load_ps(v[0])), Float4(_mm_load_ps(v[1])), Float4(_mm_load_ps(v[2]))};
}

}  // namespace

void PhongBatch::flush() {
  if (count_ == 0) return;
  for (int k = count_; k < kLanes; ++k) {  // unused lanes repeat lane 0; their results are dropped
    for (int c = 0; c < 3; ++c) P_[c][k] = P_[c][0], N_[c][k] = N_[c][0], O_[c][k] = O_[c][0], E_[c][k] = E_[c][0];
    back_[k] = back_[0];
    D_[k] = D_[0];
    material_[k] = material_[0];
  }
  for (int k = 0; k < kLanes; ++k) {
    const CourseMaterial& m = *material_[k];
    ka_[k] = m.ka, kd_[k] = m.kd, ks_[k] = m.ks, n_[k] = m.shininess, m_[k] = m.metallic;
  }
  const Vec3x4 P = load(P_);
  // N = normalize(interpolated N), then -N on a back face (two-sided lighting)
  const Vec3x4 unit = normalize3(load(N_));
  const Mask4 back{_mm_cmpneq_ps(_mm_load_ps(back_), _mm_setzero_ps())};
  const Vec3x4 N = select(back, -unit, unit);
  const LaneMaterial<Float4> material{load(E_), Float4(_mm_load_ps(ka_)), Float4(_mm_load_ps(kd_)), Float4(_mm_load_ps(ks_)),
                                      Float4(_mm_load_ps(n_)), Float4(_mm_load_ps(m_))};
  const Vec3x4 color = fogged(frame_.fog, shade(illuminate(frame_, maps_, material, P, N, viewVector<Float4>(frame_, P)), load(O_)),
                              Float4(_mm_load_ps(D_)));
  alignas(16) float rgb[3][kLanes];
  _mm_store_ps(rgb[0], color.x.v);
  _mm_store_ps(rgb[1], color.y.v);
  _mm_store_ps(rgb[2], color.z.v);
  for (int k = 0; k < count_; ++k) pixels_[offset_[k]] = {rgb[0][k], rgb[1][k], rgb[2][k], 1.0f};
  count_ = 0;
}

#else

void PhongBatch::flush() {
  for (int k = 0; k < count_; ++k) {
    const glm::vec3 P{P_[0][k], P_[1][k], P_[2][k]};
    const glm::vec3 unit = normalize3(glm::vec3{N_[0][k], N_[1][k], N_[2][k]});
    const glm::vec3 N = back_[k] != 0.0f ? -unit : unit;
    const glm::vec3 O{O_[0][k], O_[1][k], O_[2][k]};
    const glm::vec3 E{E_[0][k], E_[1][k], E_[2][k]};
    const glm::vec3 lit = shade(illuminate(frame_, maps_, laneMaterial(*material_[k], E), P, N, viewVector<float>(frame_, P)), O);
    pixels_[offset_[k]] = opaque(fogged(frame_.fog, lit, D_[k]));
  }
  count_ = 0;
}

#endif

}  // namespace facet::cpu
