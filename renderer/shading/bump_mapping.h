#pragma once
// Bump mapping (renderer/PIPELINE.md, "Bump mapping"): the
// course's perturbed normal from a height map's partial derivatives and the
// surface's. Mirror: shaders/bump_mapping.glsl.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/normal_mapping.h"
#include "shading/shading_math.h"
#include "shading/texture.h"

namespace facet {

// h at st: level 0, LINEAR, REPEAT, grey / 255.
inline float bumpHeight(const Texture& map, glm::vec2 st) {
  return sampleLevel(map.image, TexelEncoding::Linear, true, Wrap::Repeat, Wrap::Repeat, st).r;
}

// N' = N + B_u·(N × P_t) - B_v·(N × P_s) (the course's, |N| = 1) before it is normalized, with
// P_s = T = normalize3(t - N·(N·t)) and P_t = B = ±(N × T), the unit frame of normal_mapping.h;
// B_u = k·(h(s + 1/W) - h(s - 1/W))/(2/W), B_v = k·(h(t - 1/H) - h(t + 1/H))/(2/H): v = 1 - t grows up the image, as B does.
inline glm::vec3 bumped(const Texture& map, float k, glm::vec3 N, glm::vec4 tangent, glm::vec2 st) {
  const float ds = 1.0f / static_cast<float>(map.image.width()), dt = 1.0f / static_cast<float>(map.image.height());
  const float Bu = k * ((bumpHeight(map, {st.x + ds, st.y}) - bumpHeight(map, {st.x - ds, st.y})) / (2.0f * ds));
  const float Bv = k * ((bumpHeight(map, {st.x, st.y - dt}) - bumpHeight(map, {st.x, st.y + dt})) / (2.0f * dt));
  const TangentFrame f = tangentFrame(N, tangent);  // P_s = T, P_t = B
  return (N + Bu * cross3(N, f.B)) - Bv * cross3(N, f.T);
}

}  // namespace facet
