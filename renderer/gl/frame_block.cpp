#include "gl/frame_block.h"

#include <algorithm>
#include <bit>
#include <string>

#include "common/error.h"
#include "image/srgb.h"

namespace facet::gl {

// The numbers the shaders compare with (kLight* in frame_block.glsl, the
// specializations of shader_variant.cpp) are these enums' values.
static_assert(static_cast<int>(LightKind::Point) == 0 && static_cast<int>(LightKind::Directional) == 1 &&
              static_cast<int>(LightKind::Spot) == 2);
static_assert(static_cast<int>(SpecularModel::Phong) == 0 && static_cast<int>(SpecularModel::BlinnPhong) == 1);
static_assert(static_cast<int>(FogMode::None) == 0 && static_cast<int>(FogMode::Linear) == 1 && static_cast<int>(FogMode::Exponential) == 2 &&
              static_cast<int>(FogMode::Exponential2) == 3, "fog.glsl reads FACET_FOG as these values");
static_assert(static_cast<int>(ShadingMode::Flat) == 0 && static_cast<int>(ShadingMode::Gouraud) == 1 &&
              static_cast<int>(ShadingMode::Phong) == 2 && static_cast<int>(ShadingMode::Pbr) == 3);

FrameBlock makeFrameBlock(const FrameInputs& frame) {
  FrameBlock block{};
  block.eyePosition = glm::vec4(frame.eyePosition, frame.perspective ? 1.0f : 0.0f);
  block.towardEye = glm::vec4(frame.towardEye, 0.0f);
  block.ambient = glm::vec4(frame.ambient, frame.proceduralScale, frame.bump.scale, 0.0f);
  const FrameInputs::Environment& e = frame.environment;
  block.environment = glm::vec4(e.reflectivity, e.map ? 1.0f : 0.0f, showsEnvironment(frame) ? 1.0f : 0.0f,
                                e.map ? static_cast<float>(e.map->levelCount() - 1) : 0.0f);
  for (std::size_t k = 0; k < block.irradiance.size(); ++k) block.irradiance[k] = glm::vec4(e.map ? e.map->irradiance[k] : glm::vec3(0.0f), 0.0f);
  block.backgroundForward = glm::vec4(e.forward, 0.0f);
  block.backgroundRight = glm::vec4(e.right, 0.0f);
  block.backgroundUp = glm::vec4(e.up, 0.0f);
  block.shadowParams = glm::vec4(frame.shadows.biasSlope, frame.shadows.biasMin, static_cast<float>(frame.shadows.mapSize), 0.0f);
  block.background = glm::vec4(frame.background, 1.0f);
  block.fog = glm::vec4(frame.fog.start, frame.fog.end, frame.fog.density, frame.fog.cotTheta);
  block.fogColor = glm::vec4(frame.fog.color, 0.0f);
  block.fogRange = glm::vec4(frame.camera.near, frame.camera.far, 0.0f, 0.0f);
  for (std::size_t i = 0; i < frame.lights.size(); ++i) {
    const FrameLight& fl = frame.lights[i];
    LightBlock& light = block.lights[i];
    light.position = glm::vec4(fl.light.position, 1.0f);
    light.directionCosCutoff = glm::vec4(fl.light.direction, fl.cosCutoff);
    light.intensity = glm::vec4(fl.intensity, 0.0f);
    light.attenuation = glm::vec4(fl.light.attenuation, 0.0f);
    light.shadow = glm::ivec4(fl.shadowLayer, 0, 0, 0);
    light.shadowFromWorld = fl.shadowFromWorld;
  }
  return block;
}

SrgbBlock makeSrgbBlock() {
  static_assert(kSrgbBuckets <= std::tuple_size_v<decltype(SrgbBlock::buckets)>);
  const SrgbTables& tables = srgbTables();
  SrgbBlock block{};
  block.decoded = tables.decoded;
  std::copy(tables.buckets.begin(), tables.buckets.end(), block.buckets.begin());
  return block;
}

SplitSumBlock makeSplitSumBlock() {
  const SplitSumTable& table = splitSumTable();
  SplitSumBlock block{};
  for (std::size_t k = 0; k < block.entries.size(); ++k) block.entries[k] = glm::vec4(table.ab[2 * k], table.ab[2 * k + 1]);
  return block;
}

}  // namespace facet::gl
