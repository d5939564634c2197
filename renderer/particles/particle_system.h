#pragma once
// The particles of an emitter at a time T (renderer/PIPELINE.md, "Particle systems",
// "Particle systems"): Newton's laws integrated with a fixed step from each
// particle's birth, its random numbers drawn from (seed, particle index)
// alone, so that the state at T is the same for every backend, thread count
// and order of evaluation.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "vocabulary/emitter.h"
#include "vocabulary/limits.h"

namespace facet {

struct Particle {
  std::uint64_t index = 0;   // the n-th particle the emitter bore (born at startTime + n/rate)
  glm::vec3 position{0.0f};  // world space at T
  glm::vec3 velocity{0.0f};  // world units per second at T
  float age = 0.0f;          // seconds since birth, in [0, lifetime)
  glm::vec4 color{1.0f};     // linear RGB and alpha at this age
  float size = 0.0f;         // world units
};

// How many particles `emitter` has alive at `time` (those born in
// (time − lifetime, time]), counted without simulating.
std::uint64_t aliveParticleCount(const Emitter& emitter, float time);

// What no time changes about an emitter integrated with `step`: the
// settings' field table's ranges, a direction, at most kMaxStepsPerParticle
// steps a particle, and a drag the step does not overshoot. Throws
// facet::Error naming `key` ("particles.0") and the field. simulateParticles
// runs it; the settings run it as they are read.
void checkEmitter(const Emitter& emitter, float step, const std::string& key);

// The particles alive at `time`, by increasing index, integrated with the
// fixed `step` (seconds) from their birth: per step, a = g + (k/m)·(wind − v),
// v += a·step, p += v·step (semi-implicit Euler), then the ground bounce;
// the last, partial step is of the remaining time. Runs on `threads` workers
// (0: the hardware's); the result does not depend on how many.
// Throws facet::Error naming `key` ("particles.0") when the emitter would
// have more than kMaxParticles alive, or a value (`step` as the emitter's
// step) is outside the settings' field table's range for its key.
std::vector<Particle> simulateParticles(const Emitter& emitter, float time, float step, const char* key, int threads = 0);

}  // namespace facet
