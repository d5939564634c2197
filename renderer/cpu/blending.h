#pragma once
// Transparency's blending equations and the colour buffer's two ways of
// holding a colour (renderer/PIPELINE.md, section 7, "Transparency"), each
// product and sum rounded once in the order written.
// Mirror: shaders/blending.glsl.
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

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

// A fragment of linear colour C_f and alpha α (clamped to [0, 1], NaN to 0)
// over what the buffer holds at its pixel:
//   straight       t = α_b·(1 − α_f), α_o = α_f + t, C_o = (C_f·α_f + C_b·t) / α_o (0 where α_o = 0)
//   premultiplied  k = 1 − α_f, C_o = C_f·α_f + C_b·k, α_o = α_f + α_b·k
// and, additive, what is behind keeps its weight: C_b·α_b in place of C_b·t
// (straight), C_b in place of C_b·k (premultiplied); α_o as above.
inline glm::vec4 blend(glm::vec4 held, glm::vec3 fragment, float alpha, Blending blending, bool additive) {
  const float a = clampUnit(alpha);
  const glm::vec3 b(held);
  if (blending == Blending::Premultiplied) {
    const float k = 1.0f - a;
    return glm::vec4(additive ? fragment * a + b : fragment * a + b * k, a + held.a * k);
  }
  const float t = held.a * (1.0f - a);
  const float out = a + t;
  const float behind = additive ? held.a : t;
  return out > 0.0f ? glm::vec4((fragment * a + b * behind) / out, out) : glm::vec4(0.0f);
}

}  // namespace facet::cpu
