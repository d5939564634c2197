#pragma once
// The course's fog (renderer/PIPELINE.md, "Fog"), for one pixel
// or four or eight lanes: C = C_fog + f·(C - C_fog) by the eye-space depth d.
// Mirror: shaders/fog.glsl, the same operations in the same order.
#include "shading/shading_math.h"
#include "pipeline/frame_inputs.h"

namespace facet {

inline constexpr float kLog2E = 1.44269502f;  // log2 e as a float

// d from what the rasterizer interpolates: 1/w (perspective, w = z_eye·tan θ)
// or the window depth z (parallel, z = (z_eye - N)/(F - N)).
inline float eyeDepth(const FrameInputs& frame, float oneOverW, float z) {
  if (frame.perspective) return (1.0f / oneOverW) * frame.fog.cotTheta;
  return frame.camera.near + z * (frame.camera.far - frame.camera.near);
}

// f in [0, 1] (NaN: 0) of the frame's mode at depth d; fog.mode is not None.
template <class F>
F fogFactor(const FrameInputs::Fog& fog, F d) {
  F f;
  if (fog.mode == FogMode::Linear) {
    f = (F(fog.end) - d) / (F(fog.end - fog.start));
  } else {
    const F x = F(fog.density) * d;
    f = exp2Of(-((fog.mode == FogMode::Exponential ? x : x * x) * F(kLog2E)));
  }
  return minOne(maxZero(f));
}

// The colour C of a surface at depth d through the frame's fog.
template <class F>
Vec3Of<F> fogged(const FrameInputs::Fog& fog, const Vec3Of<F>& color, F d) {
  if (fog.mode == FogMode::None) return color;
  const F f = fogFactor(fog, d);
  const Vec3Of<F> C = splat<F>(fog.color);
  return C + f * (color - C);
}

}  // namespace facet
