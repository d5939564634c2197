#pragma once
// The microfacet terms of shading=pbr (renderer/PIPELINE.md, "Shading",
// "Physically based"), for float (the CPU backend's pixels, mirrored in
// shaders/physically_based.glsl) and double (the split-sum table built from
// them, pipeline/split_sum.h): one definition of each, Schlick's Fresnel
// shared with the ray tracer.
#include <cmath>

namespace facet {

inline constexpr float kPi = 3.14159274f;      // π rounded to float
inline constexpr float kMinAlpha = 0.001f;     // α = max(r², this): D stays finite on a mirror

// x⁵ = (x²·x²)·x with x = 1 - V·H: Schlick's Fresnel is F0 + (1 - F0)·x⁵.
template <class T>
T schlickWeight(T VdotH) {
  const T x = T(1) - VdotH;
  const T x2 = x * x;
  return (x2 * x2) * x;
}

// Schlick's Fresnel, F = F0 + (1 - F0)·x⁵, from x⁵ = (1 - cos θ)⁵: F0 a colour
// (shading=pbr's, x⁵ by schlickWeight) or one reflectance (the ray tracer's
// dielectrics, ray/optics.h, whose x⁵ is std::pow's: see there).
template <class C, class T>
C schlickReflectance(C F0, T x5) {
  return F0 + (C(T(1)) - F0) * x5;
}

// D = α²/(π·(d·d)), d = (N·H)²·(α² - 1) + 1 (GGX)
template <class T>
T ggxDistribution(T NdotH, T alpha2) {
  const T d = (NdotH * NdotH) * (alpha2 - T(1)) + T(1);
  return alpha2 / (T(kPi) * (d * d));
}

// Vis = 0.5/(N·L·sqrt((N·V)²(1 - α²) + α²) + N·V·sqrt((N·L)²(1 - α²) + α²)) (Smith, height-correlated)
template <class T>
T smithVisibility(T NdotL, T NdotV, T alpha2) {
  const T rest = T(1) - alpha2;
  const T towardV = NdotL * std::sqrt((NdotV * NdotV) * rest + alpha2);
  const T towardL = NdotV * std::sqrt((NdotL * NdotL) * rest + alpha2);
  return T(0.5) / (towardV + towardL);
}

}  // namespace facet
