#include "gl/frame_block.h"

#include <string>

#include "common/error.h"

namespace facet::gl {

// The numbers the shaders compare with (kLight* in frame_block.glsl, mode
// numbers in lighting.glsl) are these enums' values.
static_assert(static_cast<int>(LightKind::Point) == 0 && static_cast<int>(LightKind::Directional) == 1 &&
              static_cast<int>(LightKind::Spot) == 2);
static_assert(static_cast<int>(SpecularModel::Phong) == 0 && static_cast<int>(SpecularModel::BlinnPhong) == 1);
static_assert(static_cast<int>(ShadingMode::Flat) == 0 && static_cast<int>(ShadingMode::Gouraud) == 1 &&
              static_cast<int>(ShadingMode::Phong) == 2);

FrameBlock makeFrameBlock(const FrameInputs& frame) {
  if (frame.lights.size() > static_cast<std::size_t>(kMaxLights))
    throw Error(std::to_string(frame.lights.size()) + " lights: the OpenGL backend shades with at most " + std::to_string(kMaxLights));
  FrameBlock block{};
  block.clipFromWorld = frame.clipFromWorld;
  block.eyePosition = glm::vec4(frame.eyePosition, frame.perspective ? 1.0f : 0.0f);
  block.towardEye = glm::vec4(frame.towardEye, 0.0f);
  block.ambientCounts = glm::vec4(frame.ambient, static_cast<float>(frame.lights.size()), static_cast<float>(frame.shading),
                                  static_cast<float>(frame.specular));
  block.shadowParams = glm::vec4(frame.shadows.biasSlope, frame.shadows.biasMin, static_cast<float>(frame.shadows.pcfRadius),
                                 static_cast<float>(frame.shadows.mapSize));
  block.background = glm::vec4(frame.background, 1.0f);
  for (std::size_t i = 0; i < frame.lights.size(); ++i) {
    const FrameLight& fl = frame.lights[i];
    LightBlock& light = block.lights[i];
    light.positionKind = glm::vec4(fl.light.position, static_cast<float>(fl.light.kind));
    light.directionCosCutoff = glm::vec4(fl.light.direction, fl.cosCutoff);
    light.intensity = glm::vec4(fl.light.color * fl.light.intensity, 0.0f);  // as renderer/cpu/lighting.cpp forms I_p
    light.attenuation = glm::vec4(fl.light.attenuation, 0.0f);
    light.shadow = glm::ivec4(fl.hasShadowMap ? 1 : 0, fl.shadowLayer, 0, 0);
    light.shadowFromWorld = fl.shadowFromWorld;
  }
  return block;
}

}  // namespace facet::gl
