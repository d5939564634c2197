#pragma once
// The C++ mirror of the std140 uniform block `Frame` of shaders/frame_block.glsl,
// byte for byte: same members, same order, every member 16-byte aligned as
// std140 lays vec4, ivec4 and mat4 out. The static_asserts hold the layout
// here; tests/gl/test_frame_block.cpp compares it with the driver's offsets.
#include <array>
#include <cstddef>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "pipeline/frame_inputs.h"

namespace facet::gl {

inline constexpr int kMaxLights = 8;  // kMaxLights in frame_block.glsl

// LightData in frame_block.glsl.
struct LightBlock {
  glm::vec4 positionKind;        // xyz: world position; w: kind (LightKind as a number)
  glm::vec4 directionCosCutoff;  // xyz: world direction, unit; w: cos β (spot)
  glm::vec4 intensity;           // rgb: I_p = colour · intensity
  glm::vec4 attenuation;         // xyz: c1, c2, c3
  glm::ivec4 shadow;             // x: has a shadow map; y: its first layer in shadowMaps
  std::array<glm::mat4, 6> shadowFromWorld;  // per face: world -> shadow-map (u, v, z) after the divide
};

// Frame in frame_block.glsl.
struct FrameBlock {
  glm::mat4 clipFromWorld;   // PM·EM
  glm::vec4 eyePosition;     // xyz: P_eye; w: 1 perspective, 0 parallel
  glm::vec4 towardEye;       // xyz: -k, V under parallel projection
  glm::vec4 ambientCounts;   // x: I_a; y: light count; z: shading mode; w: specular model
  glm::vec4 shadowParams;    // x: b_slope; y: b_min; z: PCF radius r; w: map size S
  glm::vec4 background;      // rgb: linear background
  std::array<LightBlock, kMaxLights> lights;
};

// std140: a struct's members at multiples of 16, the struct padded to 16, arrays of it at that stride.
static_assert(offsetof(LightBlock, positionKind) == 0);
static_assert(offsetof(LightBlock, directionCosCutoff) == 16);
static_assert(offsetof(LightBlock, intensity) == 32);
static_assert(offsetof(LightBlock, attenuation) == 48);
static_assert(offsetof(LightBlock, shadow) == 64);
static_assert(offsetof(LightBlock, shadowFromWorld) == 80);
static_assert(sizeof(LightBlock) == 80 + 6 * 64);
static_assert(offsetof(FrameBlock, clipFromWorld) == 0);
static_assert(offsetof(FrameBlock, eyePosition) == 64);
static_assert(offsetof(FrameBlock, towardEye) == 80);
static_assert(offsetof(FrameBlock, ambientCounts) == 96);
static_assert(offsetof(FrameBlock, shadowParams) == 112);
static_assert(offsetof(FrameBlock, background) == 128);
static_assert(offsetof(FrameBlock, lights) == 144);
static_assert(sizeof(FrameBlock) == 144 + kMaxLights * sizeof(LightBlock));

// The block's values for one frame, from FrameInputs only. Throws
// facet::Error when the frame has more than kMaxLights lights.
FrameBlock makeFrameBlock(const FrameInputs& frame);

}  // namespace facet::gl
