#include "pipeline/antialiasing.h"

#include <cstdint>

#include <glm/ext/matrix_transform.hpp>

#include "pipeline/frame_inputs.h"

namespace facet {
namespace {

// SplitMix64 (Steele, Lea and Flood 2014): a fixed, portable sequence from a seed.
std::uint64_t splitMix(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// A number in [0, 1): the top 24 bits over 2^24, exact in float.
double unit(std::uint64_t& state) { return static_cast<double>(splitMix(state) >> 40) / 16777216.0; }

}  // namespace

std::vector<glm::vec2> sampleOffsets(int samplesPerSide, SamplePattern pattern, unsigned seed) {
  const int s = samplesPerSide;
  std::uint64_t state = seed;
  std::vector<glm::vec2> offsets;
  offsets.reserve(static_cast<std::size_t>(s) * static_cast<std::size_t>(s));
  for (int j = 0; j < s; ++j)
    for (int i = 0; i < s; ++i) {
      double u = 0.5, v = 0.5;
      if (pattern == SamplePattern::Jittered) u = unit(state), v = unit(state);
      offsets.push_back({static_cast<float>((i + u) / s - 0.5), static_cast<float>((j + v) / s - 0.5)});
    }
  return offsets;
}

FrameInputs sampleFrame(const FrameInputs& frame, glm::vec2 offset) {
  FrameInputs f = frame;
  // The image moves by -offset, so that each pixel's centre lands where its sample lies.
  const glm::mat4 shift = glm::translate(glm::mat4(1.0f), glm::vec3(-2.0f * offset.x / static_cast<float>(frame.width),
                                                                     -2.0f * offset.y / static_cast<float>(frame.height), 0.0f));
  f.clipFromEye = shift * frame.clipFromEye;
  f.clipFromWorld = f.clipFromEye * f.eyeFromWorld;
  for (FrameInstance& instance : f.instances) instance.clipFromModel = f.clipFromWorld * instance.worldFromModel;
  f.sampleOffset = offset;
  return f;
}

}  // namespace facet
