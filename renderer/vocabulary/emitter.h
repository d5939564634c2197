#pragma once
// A particle emitter as the course describes it (renderer/PIPELINE.md,
// "Particle systems"). The same struct describes an emitter of
// the settings (particles.N.*) and one a glTF node's extras place.
#include <array>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>

namespace facet {

// How a particle's sprite is blended over what lies behind it: `over`, the
// frame's blending equation (straight or premultiplied, the `blending`
// key), or `additive`, which adds its light without hiding what is behind
// (renderer/PIPELINE.md, "Transparency").
enum class SpriteBlending { Over, Additive, Count };
inline constexpr std::array<std::string_view, static_cast<int>(SpriteBlending::Count)> kSpriteBlendingNames = {"over", "additive"};

inline constexpr float kDefaultParticleStep = 1.0f / 240.0f;  // seconds

struct Emitter {
  glm::vec3 position{0.0f, 0.0f, 0.0f};   // world space: where particles are born
  float rate = 200.0f;                     // particles born per second, one every 1/rate s from time 0
  float startTime = 0.0f;                  // seconds: the first is born then
  glm::vec3 direction{0.0f, 1.0f, 0.0f};  // world space: the initial velocity's mean direction
  float spread = 15.0f;                    // degrees: velocities lie in a cone of this half-angle around it, uniform over its solid angle
  float speed = 4.0f;                      // world units per second
  float speedSpread = 0.5f;                // speeds uniform in [speed − speedSpread, speed + speedSpread]
  float lifetime = 2.5f;                   // seconds a particle lives
  glm::vec3 startColor{0.6f, 0.8f, 1.0f};  // linear RGB at birth
  glm::vec3 endColor{0.1f, 0.3f, 0.9f};    // linear RGB at death, linear in age between
  float startAlpha = 0.9f, endAlpha = 0.0f;
  float startSize = 0.08f, endSize = 0.16f; // world units: the sprite's side
  float mass = 0.01f;                      // kg: a = F / m
  glm::vec3 gravity{0.0f, -9.81f, 0.0f};  // m/s², acceleration on every particle
  float drag = 0.002f;                     // k of the drag force F = k·(wind − v), kg/s
  glm::vec3 wind{0.0f, 0.0f, 0.0f};       // m/s: the air's velocity
  bool ground = true;                      // collide with the plane y = groundHeight
  float groundHeight = 0.0f;
  float restitution = 0.4f;                // the share of the normal speed kept at a bounce
  float friction = 0.2f;                   // the share of the tangential speed lost at a bounce
  std::string sprite;                      // a PNG with alpha; empty: a built-in soft disc
  SpriteBlending blending = SpriteBlending::Over;
  bool castsShadow = false;                // the sprites are drawn into the shadow maps (where α ≥ transparency.shadowCutoff)
  int seed = 1;                            // the generator's seed: the same seed, the same particles
  float step = kDefaultParticleStep;       // seconds: the fixed step of the integration (simulateParticles is given it)
};

}  // namespace facet
