#pragma once
// Environment mapping (renderer/PIPELINE.md, "Textures"): the cube map's
// linear RGB in a direction, for the reflection k_r·I_r and the background.
// Mirror: shaders/environment.glsl — same functions, same order.
#include <algorithm>

#include <glm/vec3.hpp>

#include "shading/texture.h"
#include "shading/blending.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/light_frustum.h"
#include "scene/scene.h"

namespace facet {

// env(D) at mip level k: the face of D's largest component (cubeFace),
// OpenGL's (sc, tc, ma) for it, LINEAR within the face, clamped to its edges.
inline glm::vec3 environmentAt(const EnvironmentMap& map, glm::vec3 D, int level) {
  const int face = cubeFace(D);
  float sc = 0, tc = 0, ma = 0;
  switch (face) {
    case 0: sc = -D.z, tc = -D.y, ma = D.x; break;
    case 1: sc = D.z, tc = -D.y, ma = -D.x; break;
    case 2: sc = D.x, tc = D.z, ma = D.y; break;
    case 3: sc = D.x, tc = -D.z, ma = -D.y; break;
    case 4: sc = D.x, tc = -D.y, ma = D.z; break;
    default: sc = -D.x, tc = -D.y, ma = -D.z; break;
  }
  const float s = (sc / ma + 1.0f) * 0.5f, t = (tc / ma + 1.0f) * 0.5f;
  const int n = std::max(1, map.faceSize() >> level);
  return glm::vec3(sampleRegion(map.level(level), TexelEncoding::Srgb, {face * n, 0}, {n, n}, true, Wrap::ClampToEdge, Wrap::ClampToEdge, {s, t}));
}

// The linear colour of empty pixel (px, py) seen at `offset` from its centre:
// env(D), D = (F + x·X) + y·Y with x, y that position in NDC, where the frame
// shows its map; else the background.
inline glm::vec3 backgroundAt(const FrameInputs& frame, int px, int py, glm::vec2 offset) {
  if (!showsEnvironment(frame)) return frame.background;
  const FrameInputs::Environment& e = frame.environment;
  const float x = (2.0f * ((static_cast<float>(px) + 0.5f) + offset.x)) / static_cast<float>(frame.width) - 1.0f;
  const float y = (2.0f * ((static_cast<float>(py) + 0.5f) + offset.y)) / static_cast<float>(frame.height) - 1.0f;
  return environmentAt(*e.map, (e.forward + x * e.right) + y * e.up, 0);
}

// The same at the frame's sample offset (anti-aliasing; the centre for one sample).
inline glm::vec3 backgroundAt(const FrameInputs& frame, int px, int py) { return backgroundAt(frame, px, py, frame.sampleOffset); }

// What the colour buffer is cleared to at (px, py): its background with backgroundAlpha, as the frame's blending holds it.
inline glm::vec4 backgroundPixel(const FrameInputs& frame, int px, int py) { return stored(backgroundAt(frame, px, py), frame.backgroundAlpha, frame.blending); }

}  // namespace facet
