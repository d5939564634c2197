#pragma once
// Transparency's blending equations and the colour buffer's two ways of
// holding a colour (renderer/PIPELINE.md, section 7, "Transparency"), each
// product and sum rounded once in the order written.
// Mirror: shaders/blending.glsl.
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "cpu/lanes.h"
#include "cpu/shading_math.h"
#include "image/srgb.h"
#include "settings/render_settings.h"

namespace facet::cpu {

// An opaque fragment's colour as the buffer holds it, whichever the blending (C·1 = C):
// what every opaque surface, line and point writes. Mirror: writeLit in shaders/lit_output.glsl.
inline glm::vec4 opaque(glm::vec3 color) { return glm::vec4(color, 1.0f); }

// A colour C with alpha a as the buffer holds it: (C, a) straight, (C·a, a) premultiplied.
inline glm::vec4 stored(glm::vec3 color, float alpha, Blending blending) {
  return blending == Blending::Premultiplied ? glm::vec4(color * alpha, alpha) : glm::vec4(color, alpha);
}

// The straight colour of what the buffer holds: premultiplied, C·a / a where a > 0, else 0.
inline glm::vec4 unstored(glm::vec4 held, Blending blending) {
  if (blending != Blending::Premultiplied) return held;
  return held.a > 0.0f ? glm::vec4(glm::vec3(held) / held.a, held.a) : glm::vec4(0.0f, 0.0f, 0.0f, held.a);
}

// What the buffer holds as premultiplied (C·a, a), the form samples are averaged in (anti-aliasing).
inline glm::vec4 premultipliedOf(glm::vec4 held, Blending blending) {
  return blending == Blending::Premultiplied ? held : glm::vec4(glm::vec3(held) * held.a, held.a);
}

// What the buffer holds at a pixel, for F's lanes: colour and alpha.
template <class F>
struct HeldColor {
  Vec3Of<F> color;
  F alpha;
};

// A fragment of linear colour C_f and alpha α (clamped to [0, 1], NaN to 0)
// over what the buffer holds at its pixel:
//   straight       t = α_b·(1 − α_f), α_o = α_f + t, C_o = (C_f·α_f + C_b·t) / α_o (0 where α_o = 0)
//   premultiplied  k = 1 − α_f, C_o = C_f·α_f + C_b·k, α_o = α_f + α_b·k
// and, additive, what is behind keeps its weight: C_b·α_b in place of C_b·t
// (straight), C_b in place of C_b·k (premultiplied); α_o as above.
// One pixel (F = float) or four or eight at a time, the same operations per lane.
template <class F>
HeldColor<F> blendLanes(const HeldColor<F>& held, const Vec3Of<F>& fragment, F alpha, Blending blending, bool additive) {
  const F a = select(alpha > F(0.0f), minOne(alpha), F(0.0f));  // clampUnit
  const Vec3Of<F>& b = held.color;
  if (blending == Blending::Premultiplied) {
    const F k = F(1.0f) - a;
    return {additive ? fragment * a + b : fragment * a + b * k, a + held.alpha * k};
  }
  const F t = held.alpha * (F(1.0f) - a);
  const F out = a + t;
  const F behind = additive ? held.alpha : t;
  const auto some = out > F(0.0f);
  return {select(some, (fragment * a + b * behind) / out, splat<F>(glm::vec3(0.0f))), select(some, out, F(0.0f))};
}

inline glm::vec4 blend(glm::vec4 held, glm::vec3 fragment, float alpha, Blending blending, bool additive) {
  const HeldColor<float> out = blendLanes<float>({glm::vec3(held), held.a}, fragment, alpha, blending, additive);
  return glm::vec4(out.color, out.alpha);
}

// How a pass writes its fragments into the colour buffer: blended (with each
// pixel's α, by the frame's equation, additive or not) rather than opaque.
struct BlendOver {
  Blending blending;
  bool additive;
};

// A shaded colour C written where the buffer holds `held`: opaque (C, 1), or blended over it with α.
inline void writeFragment(glm::vec4& held, glm::vec3 C, float alpha, const BlendOver* over) {
  held = over ? blend(held, C, alpha, over->blending, over->additive) : opaque(C);
}

#if defined(__SSE2__)
// blend for up to four pixels at once, four lanes: lanes [0, count) of
// `color` and `alpha` over the RGBA pixels at rgba + 4·offsets[k] (a
// transpose in registers each way; the lanes past count read and write nothing).
inline void blendPixels(float* rgba, const std::size_t* offsets, int count, const Vec3x4& color, Float4 alpha, const BlendOver& over) {
  __m128 pixel[4];
  for (int k = 0; k < 4; ++k) pixel[k] = k < count ? _mm_loadu_ps(rgba + 4 * offsets[k]) : _mm_setzero_ps();
  _MM_TRANSPOSE4_PS(pixel[0], pixel[1], pixel[2], pixel[3]);
  const HeldColor<Float4> held{{Float4(pixel[0]), Float4(pixel[1]), Float4(pixel[2])}, Float4(pixel[3])};
  const HeldColor<Float4> out = blendLanes<Float4>(held, color, alpha, over.blending, over.additive);
  pixel[0] = out.color.x.v, pixel[1] = out.color.y.v, pixel[2] = out.color.z.v, pixel[3] = out.alpha.v;
  _MM_TRANSPOSE4_PS(pixel[0], pixel[1], pixel[2], pixel[3]);
  for (int k = 0; k < count && k < 4; ++k) _mm_storeu_ps(rgba + 4 * offsets[k], pixel[k]);
}

// The same for a wider lane type (eight, sixteen, or twice either), four lanes at a time.
template <class F>
void blendPixels(float* rgba, const std::size_t* offsets, int count, const Vec3Of<F>& color, F alpha, const BlendOver& over) {
  constexpr int kLanes = kLaneCount<F>;
  alignas(64) float c[3][kLanes], a[kLanes];
  storeLanes(c[0], color.x), storeLanes(c[1], color.y), storeLanes(c[2], color.z), storeLanes(a, alpha);
  for (int q = 0; q < count; q += 4)
    blendPixels(rgba, offsets + q, count - q, Vec3x4(Float4(_mm_load_ps(c[0] + q)), Float4(_mm_load_ps(c[1] + q)), Float4(_mm_load_ps(c[2] + q))),
                Float4(_mm_load_ps(a + q)), over);
}
#endif

}  // namespace facet::cpu
