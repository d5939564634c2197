#pragma once
// Transparency's blending equations and the colour buffer's two ways of
// holding a colour (renderer/PIPELINE.md, "Transparency"), each
// product and sum rounded once in the order written.
// Mirror: shaders/blending.glsl.
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/lanes.h"
#include "shading/shading_math.h"
#include "image/srgb.h"
#include "settings/render_settings.h"

namespace facet {

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

// blend for up to F's width of pixels at once: lanes [0, count) of `color`
// and `alpha` over the RGBA pixels at rgba + 4·offsets[k] (loadPixels and
// storePixels, lanes.h; the lanes past count read and write nothing).
template <class F>
void blendPixels(float* rgba, const std::size_t* offsets, int count, const Vec3Of<F>& color, F alpha, const BlendOver& over) {
  HeldColor<F> held;
  loadPixels(rgba, offsets, count, held.color, held.alpha);
  const HeldColor<F> out = blendLanes<F>(held, color, alpha, over.blending, over.additive);
  storePixels(rgba, offsets, count, out.color, out.alpha);
}

}  // namespace facet
