#pragma once
#include <array>
#include <string_view>

#include <glm/vec3.hpp>

namespace facet {

enum class LightKind { Point, Directional, Spot, Count };
inline constexpr std::array<std::string_view, static_cast<int>(LightKind::Count)> kLightKindNames = {
    "point", "directional", "spot"};

// A light of the course's illumination equation. The same struct describes a
// scene's light and a light written in RenderSettings.
struct Light {
  LightKind kind = LightKind::Point;
  glm::vec3 position{0.0f, 5.0f, 0.0f};     // world space (point, spot)
  glm::vec3 direction{0.0f, -1.0f, 0.0f};   // world space, where the light shines (directional, spot)
  glm::vec3 color{1.0f, 1.0f, 1.0f};        // linear RGB
  float intensity = 1.0f;                   // I_p = intensity · color
  glm::vec3 attenuation{1.0f, 0.0f, 0.0f};  // c1, c2, c3 of f_att = min(1, 1/(c1 + c2·d + c3·d²))
  float spotCutoffDeg = 30.0f;              // β: lit where dot(-L, D) > cos β (spot)
  bool castsShadow = true;
  // The ray tracer's soft shadows (renderer/PIPELINE.md, "Ray tracing"): a point
  // or spot light is a sphere of this radius (world units), a directional
  // light a cone of this half-angle (degrees); 0 is a point, a hard shadow.
  float radius = 0.0f;
};

}  // namespace facet
