// Transparency's blending equations and the colour buffer's two ways of
// holding a colour (renderer/PIPELINE.md, "Transparency"), each
// product and sum rounded once in the order written. Mirror:
// renderer/shading/blending.h.

// A colour C with alpha a as the buffer holds it: (C, a) straight, (C·a, a) premultiplied.
vec4 stored(vec3 color, float alpha, bool premultiplied) {
  precise vec3 scaled = color * alpha;
  return premultiplied ? vec4(scaled, alpha) : vec4(color, alpha);
}

// The straight colour of what the buffer holds: premultiplied, C·a / a where a > 0, else 0.
vec4 unstored(vec4 held, bool premultiplied) {
  precise vec3 divided = held.rgb / held.a;
  if (!premultiplied) return held;
  return held.a > 0.0 ? vec4(divided, held.a) : vec4(vec3(0.0), held.a);
}

// What the buffer holds as premultiplied (C·a, a), the form samples are averaged in (anti-aliasing).
vec4 premultipliedOf(vec4 held, bool premultiplied) {
  precise vec3 scaled = held.rgb * held.a;
  return premultiplied ? held : vec4(scaled, held.a);
}

// A fragment of linear colour C_f and alpha α (clamped to [0, 1], NaN to 0)
// over what the buffer holds at its pixel:
//   straight       t = α_b·(1 − α_f), α_o = α_f + t, C_o = (C_f·α_f + C_b·t) / α_o (0 where α_o = 0)
//   premultiplied  k = 1 − α_f, C_o = C_f·α_f + C_b·k, α_o = α_f + α_b·k
// and, additive, what is behind keeps its weight: C_b·α_b in place of C_b·t
// (straight), C_b in place of C_b·k (premultiplied); α_o as above.
vec4 blend(vec4 held, vec3 fragment, float alpha, bool premultiplied, bool additive) {
  float a = alpha > 0.0 ? (alpha < 1.0 ? alpha : 1.0) : 0.0;
  if (premultiplied) {
    precise float k = 1.0 - a;
    precise vec3 c = additive ? fragment * a + held.rgb : fragment * a + held.rgb * k;
    precise float outAlpha = a + held.a * k;
    return vec4(c, outAlpha);
  }
  precise float t = held.a * (1.0 - a);
  precise float outAlpha = a + t;
  precise float behind = additive ? held.a : t;
  precise vec3 c = (fragment * a + held.rgb * behind) / outAlpha;
  return outAlpha > 0.0 ? vec4(c, outAlpha) : vec4(0.0);
}
