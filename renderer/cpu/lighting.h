#pragma once
// The course's illumination equation on the CPU.
// Mirror: shaders/lighting.glsl — the same functions, in the same order, with
// the same names and arguments. Change one, change the other.
//
//   I = k_e + k_a·I_a·O_d + Σ_lights S·f_att·(k_d·I_p·max(N·L, 0)·O_d + k_s·I_p·spec)
#include <glm/vec3.hpp>

#include "cpu/shadow_maps.h"
#include "pipeline/frame_inputs.h"

namespace facet::cpu {

// f_att = min(1, 1/(c1 + c2·d + c3·d²))
float attenuation(glm::vec3 c, float d);

// spec = max(R·V, 0)^n with R = 2(L·N)N - L (Phong), or max(N·H, 0)^n with
// H = normalize(L + V) (Blinn-Phong). The caller skips it where N·L ≤ 0.
float specularTerm(glm::vec3 N, glm::vec3 L, glm::vec3 V, float shininess, SpecularModel model);

// S of one light at world point P: PCF over (2r+1)² texels of the light's
// map, a texel in shadow when z - bias > depth, bias = max(b_slope·(1 - N·L), b_min).
// Outside the map (or beyond its far plane) counts as lit.
float shadowFactor(const ShadowMaps& maps, const FrameLight& light, const ShadowSettings& shadows, glm::vec3 P, glm::vec3 N, glm::vec3 L);

// I split in the part O_d multiplies and the rest, so that a textured O_d can
// be applied per pixel when lighting is per vertex (Gouraud) or per triangle (flat):
//   I = O_d·diffuse + specular
//   diffuse  = k_a·I_a + Σ S·f_att·k_d·I_p·max(N·L, 0)
//   specular = k_e + Σ S·f_att·k_s·I_p·spec
struct Illumination {
  glm::vec3 diffuse{0.0f};
  glm::vec3 specular{0.0f};
};

// Illumination at world point P with unit normal N and unit view vector V.
Illumination illuminate(const FrameInputs& frame, const ShadowMaps& maps, const CourseMaterial& material, glm::vec3 P, glm::vec3 N,
                        glm::vec3 V);

// I = O_d·diffuse + specular (linear, unclamped).
glm::vec3 shade(const Illumination& illumination, glm::vec3 baseColor);

// V at P: toward the eye (perspective) or the constant -k (parallel).
glm::vec3 viewVector(const FrameInputs& frame, glm::vec3 P);

// Clamp to [0,1], then IEC 61966-2-1: 12.92·c below 0.0031308, else 1.055·c^(1/2.4) - 0.055.
glm::vec3 encodeSrgb(glm::vec3 linear);

// sRGB-encoded [0,1] to 8 bits, rounding to nearest.
unsigned char quantize(float encoded);

}  // namespace facet::cpu
