#pragma once
// What a Phong batch (phong_batch.h) shades on its lanes: the queued
// pixels' inputs, one column per lane, and the shading of F's width of them
// (Float4, Float8 or Float16), the same steps as one pixel's in lit_pass.cpp.
#include "cpu/blending.h"
#include "cpu/fog.h"
#include "cpu/lighting.h"

namespace facet::cpu {

struct PhongLanes {
  static constexpr int kMost = 32;  // twice sixteen lanes (lane_pairs.h); each column aligned for 512-bit loads
  alignas(64) float P[3][kMost], N[3][kMost], O[3][kMost], E[3][kMost], D[kMost], back[kMost];
  alignas(64) float ka[kMost], kd[kMost], ks[kMost], n[kMost], m[kMost];
  alignas(64) float alpha[kMost];  // a blended pass's α (BlendOver); unread by an opaque one
};

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
  const auto vec3 = [&](const float (&columns)[3][PhongLanes::kMost]) { return Vec3(lanes(columns[0]), lanes(columns[1]), lanes(columns[2])); };
  const Vec3 P = vec3(in.P);
  // N = normalize(interpolated N), then -N on a back face (two-sided lighting; back is 0 or 1)
  const Vec3 unit = normalize3(vec3(in.N));
  const Vec3 N = select(F(0.0f) < lanes(in.back), -unit, unit);
  const LaneMaterial<F> material{vec3(in.E), lanes(in.ka), lanes(in.kd), lanes(in.ks), lanes(in.n), lanes(in.m)};
  const Vec3 color = fogged(frame.fog, shade(illuminate(frame, maps, material, P, N, viewVector<F>(frame, P)), vec3(in.O)), lanes(in.D));
  if (over) blendPixels(rgba, offsets + first, count - first, color, lanes(in.alpha), *over);
  else storeOpaquePixels(rgba, offsets + first, count - first, color);
}

}  // namespace facet::cpu
