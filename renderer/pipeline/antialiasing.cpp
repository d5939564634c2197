#include "pipeline/antialiasing.h"

#include <glm/ext/matrix_transform.hpp>

#include "common/random.h"
#include "pipeline/frame_inputs.h"

namespace facet {

std::vector<glm::vec2> sampleOffsets(int samplesPerSide, SamplePattern pattern, unsigned seed) {
  const int s = samplesPerSide;
  SplitMix64 random(seed);
  std::vector<glm::vec2> offsets;
  offsets.reserve(static_cast<std::size_t>(s) * static_cast<std::size_t>(s));
  for (int j = 0; j < s; ++j)
    for (int i = 0; i < s; ++i) {
      double u = 0.5, v = 0.5;
      if (pattern == SamplePattern::Jittered) u = random.unitFloat(), v = random.unitFloat();  // k/2^24, exact in float and double
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
