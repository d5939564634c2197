#pragma once
// The C++ mirror of the std140 uniform block `Frame` of shaders/frame_block.glsl,
// byte for byte: same members, same order, every member 16-byte aligned as
// std140 lays vec4, ivec4 and mat4 out. The static_asserts hold the layout
// here; tests/gl/test_frame_block.cpp compares it with the driver's offsets.
#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "image/srgb.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/split_sum.h"

namespace facet::gl {

// The block holds facet::kMaxLights lights (render_settings.h); the shaders
// get the same number as FACET_MAX_LIGHTS (shader_program.cpp).

// LightData in frame_block.glsl.
struct LightBlock {
  glm::vec4 position;            // xyz: world position (point, spot)
  glm::vec4 directionCosCutoff;  // xyz: world direction, unit; w: cos β (spot)
  glm::vec4 intensity;           // rgb: I_p = colour · intensity
  glm::vec4 attenuation;         // xyz: c1, c2, c3
  glm::ivec4 shadow;             // x: the first layer of its faces in shadowMaps
  std::array<glm::mat4, 6> shadowFromWorld;  // per face: world -> shadow-map (u, v, z) after the divide
};

// Frame in frame_block.glsl. What the lit programs are specialized on (light
// count and kinds, shadowed lights, specular model, PCF radius) is not here.
struct FrameBlock {
  glm::vec4 eyePosition;     // xyz: P_eye; w: 1 perspective, 0 parallel
  glm::vec4 towardEye;       // xyz: -k, V under parallel projection
  glm::vec4 ambient;         // x: I_a; y: k of the procedural texture; z: k of the bump map
  glm::vec4 shadowParams;    // x: b_slope; y: b_min; z: map size S
  glm::vec4 background;      // rgb: linear background
  std::array<LightBlock, facet::kMaxLights> lights;
  glm::vec4 environment;     // x: k_r; y: 1 with a map; z: 1 when empty pixels show it; w: its last mip level
  glm::vec4 backgroundForward, backgroundRight, backgroundUp;  // xyz: D = (F + x·X) + y·Y
  std::array<glm::vec4, 9> irradiance;  // rgb: the map's E(N)/π coefficients (EnvironmentMap::irradiance)
  glm::vec4 fog;             // x: start; y: end; z: density; w: cot θ (fog.glsl)
  glm::vec4 fogColor;        // rgb: C_fog, linear
  glm::vec4 fogRange;        // x: N, y: F of the camera (parallel projection's eye depth)
};

// SrgbTables in srgb.glsl: image/srgb.h's decoded values and bucket
// entries, four to a vec4 or uvec4, as std140 arrays of scalars would pad
// each element to 16 bytes.
struct SrgbBlock {
  std::array<float, 256> decoded;             // 64 vec4
  std::array<std::uint32_t, 833 * 4> buckets;  // kSrgbBuckets used, padded to 833 uvec4
};
static_assert(offsetof(SrgbBlock, buckets) == 64 * 16);
static_assert(sizeof(SrgbBlock) == (64 + 833) * 16);

// SplitSumTable in physically_based.glsl: pipeline/split_sum.h's (A, B) entries, two to a vec4.
struct SplitSumBlock {
  std::array<glm::vec4, kSplitSumSize * kSplitSumSize / 2> entries;
};
static_assert(sizeof(SplitSumBlock) == kSplitSumSize * kSplitSumSize * 8);

// std140: a struct's members at multiples of 16, the struct padded to 16, arrays of it at that stride.
static_assert(offsetof(LightBlock, position) == 0);
static_assert(offsetof(LightBlock, directionCosCutoff) == 16);
static_assert(offsetof(LightBlock, intensity) == 32);
static_assert(offsetof(LightBlock, attenuation) == 48);
static_assert(offsetof(LightBlock, shadow) == 64);
static_assert(offsetof(LightBlock, shadowFromWorld) == 80);
static_assert(sizeof(LightBlock) == 80 + 6 * 64);
static_assert(offsetof(FrameBlock, eyePosition) == 0);
static_assert(offsetof(FrameBlock, towardEye) == 16);
static_assert(offsetof(FrameBlock, ambient) == 32);
static_assert(offsetof(FrameBlock, shadowParams) == 48);
static_assert(offsetof(FrameBlock, background) == 64);
static_assert(offsetof(FrameBlock, lights) == 80);
static_assert(kSrgbBuckets <= 2033 * 16);
static_assert(offsetof(FrameBlock, environment) == 80 + facet::kMaxLights * sizeof(LightBlock));
static_assert(offsetof(FrameBlock, backgroundUp) == offsetof(FrameBlock, environment) + 48);
static_assert(offsetof(FrameBlock, irradiance) == offsetof(FrameBlock, environment) + 64);
static_assert(offsetof(FrameBlock, fog) == offsetof(FrameBlock, irradiance) + 9 * 16);
static_assert(sizeof(FrameBlock) == 80 + facet::kMaxLights * sizeof(LightBlock) + 64 + 9 * 16 + 3 * 16);

// The block's values for one frame, from FrameInputs only (checkFrame has
// held its light count to kMaxLights).
FrameBlock makeFrameBlock(const FrameInputs& frame);

// The sRGB tables, once per renderer.
SrgbBlock makeSrgbBlock();

// The split-sum table, once per renderer that draws shading=pbr.
SplitSumBlock makeSplitSumBlock();

}  // namespace facet::gl
