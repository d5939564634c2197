#pragma once
// What a Phong batch (phong_batch.h) shades on its lanes: the queued
// pixels' inputs, one column per lane, and the shading of F's width of them
// (Float4, Float8 or Float16), by the Phong program's lighting (shading/lit_programs.h).
#include "shading/blending.h"
#include "shading/fog.h"
#include "cpu/interpolation.h"
#include "shading/lighting.h"
#include "shading/lit_programs.h"

namespace facet::cpu {

struct PhongLanes {
  static constexpr int kMost = 32;  // twice sixteen lanes (lane_pairs.h)
  // A column holds kMost lanes and room for a run's store of sixteen past
  // the last one queued (queueRunLanes); each is aligned for 512-bit loads.
  static constexpr int kColumn = kMost + 16;
  alignas(64) float P[3][kColumn], N[3][kColumn], O[3][kColumn], E[3][kColumn], D[kColumn], back[kColumn];
  alignas(64) float ka[kColumn], kd[kColumn], ks[kColumn], n[kColumn], m[kColumn];
  alignas(64) float alpha[kColumn];  // a blended pass's α (BlendOver); unread by an opaque one
};

// F's width of pixels (px, py), (px+1, py), ... of one triangle queued at
// lanes [at, at + width) (any at below kMost): P and N (varyings 0-2 and
// 3-5 of `in`, set up) by Interpolation's operations (each plane's two
// fused multiply-adds, 1 / plane(1/w), the product), the offsets offset,
// offset+1, ..., α from alpha[0..width) (null: 1), the facing, O_d and the
// material. A run of n pixels, n below the width, is queued this way too:
// the batch counts n lanes, and the next pixels queued or its padding
// (PhongBatch::flush) write over the rest. So the columns have room past
// the last lane, and the tile's arrays past its last pixel for α
// (frame_buffers.h).
template <class F>
void queueRunLanes(const Interpolation& in, int px, int py, std::size_t offset, bool back, glm::vec3 baseColor,
                   const CourseMaterial& material, const float* alpha, PhongLanes& lanes, std::size_t* offsets, int at) {
  alignas(64) static constexpr float kLane[16] = {0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f, 8.0f, 9.0f, 10.0f, 11.0f, 12.0f, 13.0f, 14.0f, 15.0f};
  F lane;
  loadLanes(lane, kLane);
  const F x = F(static_cast<float>(px)) + lane, y(static_cast<float>(py));
  const auto planeAt = [&](const Plane& p) { return fusedMultiplyAdd(F(p.dady), y, fusedMultiplyAdd(F(p.dadx), x, F(p.a0))); };
  const F w = F(1.0f) / planeAt(in.oneOverWPlane());
  const auto put = [&](float* column, F v) { storeLanesUnaligned(column + at, v); };
  for (int c = 0; c < 3; ++c) {
    put(lanes.P[c], planeAt(in.varyingPlane(c)) * w);
    put(lanes.N[c], planeAt(in.varyingPlane(3 + c)) * w);
    put(lanes.O[c], F(baseColor[c]));
    put(lanes.E[c], F(material.emissive[c]));
  }
  put(lanes.back, F(back ? 1.0f : 0.0f));
  put(lanes.ka, F(material.ka)), put(lanes.kd, F(material.kd)), put(lanes.ks, F(material.ks));
  put(lanes.n, F(material.shininess)), put(lanes.m, F(material.metallic));
  F a(1.0f);
  if (alpha) loadLanesUnaligned(a, alpha);
  put(lanes.alpha, a);
  for (int k = 0; k < kLaneCount<F>; ++k) offsets[at + k] = offset + static_cast<std::size_t>(k);
}

// Lanes [first, first + width of F) shaded; those below count written to the RGBA pixels at
// rgba + 4·offsets[lane]: opaque, or blended over them with their α where `over` is given.
template <class F>
void shadeLanes(const FrameInputs& frame, const ShadowMaps& maps, const PhongLanes& in, int first, float* rgba, const std::size_t* offsets, int count,
                const BlendOver* over) {
  using Vec3 = Vec3Of<F>;
  const auto lanes = [&](const float* column) {
    F x;
    loadLanes(x, column + first);
    return x;
  };
  const auto vec3 = [&](const float (&columns)[3][PhongLanes::kColumn]) { return Vec3(lanes(columns[0]), lanes(columns[1]), lanes(columns[2])); };
  // lit_phong.frag's lighting on the lanes (back is 0 or 1: the lanes whose N is negated)
  const Vec3 P = vec3(in.P);
  const Vec3 N = LitPhongProgram::twoSided<F>(vec3(in.N), F(0.0f) < lanes(in.back));
  const LaneMaterial<F> material{vec3(in.E), lanes(in.ka), lanes(in.kd), lanes(in.ks), lanes(in.n), lanes(in.m)};
  const Vec3 color = fogged(frame.fog, shade(LitPhongProgram::lit<F>(frame, maps, material, P, N), vec3(in.O)), lanes(in.D));
  if (over) blendPixels(rgba, offsets + first, count - first, color, lanes(in.alpha), *over);
  else storePixels(rgba, offsets + first, count - first, color, F(1.0f));  // opaque: (C, 1)
}

}  // namespace facet::cpu
