#pragma once
// One pixel of a frame, explained: which triangle the z-buffer kept there,
// the pixel centre's perspective-correct barycentric weights in it, the
// point P, the normal N, the view vector V, and for each light L, N·L, f_att,
// R or H, the specular power, the shadow test (the texel read, the depth in
// it, the depth compared, the bias, the PCF count) and its two terms of the
// course's illumination equation
//
//   I = k_e + k_a·I_a·O_d + Σ_lights S·f_att·(k_d·I_p·max(N·L, 0)·O_d + k_s·I_p·spec·O_s)
//
// computed by the CPU backend's own functions (shading/lighting.h), then the
// colour they sum to and the pixel the backend drew. What the viewer shows
// for a clicked pixel and `facet render --probe X,Y` prints.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "image/image.h"
#include "pipeline/frame_inputs.h"
#include "scene/scene.h"

namespace facet {

struct ProbedLight {
  glm::vec3 L{0.0f};           // unit, from P toward the light
  float NdotL = 0, fAtt = 1;
  bool reaches = true;         // a spot's cone reaches P (always, for other kinds)
  bool lit = false;            // reaches and N·L > 0: the light adds its terms
  glm::vec3 RorH{0.0f};        // R = 2(L·N)N - L (phong) or H = normalize(L + V) (blinn-phong)
  float specularBase = 0;      // R·V or N·H, before max(·, 0)^n
  float spec = 0;              // max(·, 0)^n
  // The shadow test (shading/lighting.h, shadowLookup and shadowFactor).
  bool shadowMapped = false;   // the light has a shadow map
  bool outsideMap = false;     // P is read as lit without a read (behind the light, beyond its far plane)
  int face = 0, texelX = 0, texelY = 0;  // the face (0..5 for a point light) and texel holding (u, v)
  float depthRead = 1;         // the map's depth in that texel
  float depthCompared = 0;     // z of P in the light's window coordinates
  float bias = 0;              // max(b_slope (1 - N·L), b_min)
  float S = 1;                 // the share of the PCF taps that are lit
  glm::vec3 diffuse{0.0f};     // S·f_att·k_d·I_p·max(N·L, 0)·O_d
  glm::vec3 specular{0.0f};    // S·f_att·k_s·I_p·spec·O_s
};

struct PixelProbe {
  int x = 0, y = 0;                // the pixel, from the bottom left as Image stores it
  bool covered = false;            // a triangle covers it (else the background)
  std::uint32_t triangle = 0;      // as FrameOutput::TriangleIds numbers it: 1 + the frame's triangle index
  int instance = 0;                // into FrameInputs::instances
  std::uint32_t meshTriangle = 0;  // the triangle within its mesh
  glm::vec3 weights{0.0f};         // perspective-correct barycentric weights of the pixel centre (sum 1)
  glm::vec3 vertices[3]{};         // the triangle's corners, world space
  glm::vec3 P{0.0f}, N{0.0f}, V{0.0f};  // where and with which normal the illumination equation is evaluated
  std::string shadingNote;         // how the mode uses them (flat: the centroid; gouraud: at the vertices)
  // The material's course coefficients.
  glm::vec3 baseColor{0.0f};       // O_d (the base colour factor times the vertex colour; a texture's texel is not in it)
  glm::vec3 specularColor{0.0f};   // O_s = (1 - m) + m·O_d
  glm::vec3 emissive{0.0f};        // k_e
  float ka = 0, kd = 0, ks = 0, shininess = 1;
  glm::vec3 ambient{0.0f};         // k_a·I_a·O_d
  std::vector<ProbedLight> lights;  // in FrameInputs order
  glm::vec3 sum{0.0f};             // I, linear: the terms above summed
  glm::vec3 shaded{0.0f};          // I as the lit pass computes it (shading/lighting.h, illuminate and shade)
  Rgba8 encoded{};                 // `shaded` encoded to sRGB, as the resolve writes it
  Rgba8 drawn{};                   // the pixel the CPU backend drew
};

// Throws facet::Error for a pixel outside the frame.
PixelProbe probePixel(const Scene& scene, const FrameInputs& frame, int x, int y);

// The probe as lines of text, for a terminal or the viewer's panel.
std::vector<std::string> describeProbe(const PixelProbe& probe);

}  // namespace facet
