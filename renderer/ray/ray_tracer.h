#pragma once
// The course's recursive ray tracing (renderer/PIPELINE.md, "Ray tracing"):
// a primary ray per pixel (and sample), the fragment stage of the
// rasterizers at each hit with shadow rays for S, and the reflected and
// transmitted rays of
//   I = (1 - k_t)·O_d·diffuse + specular + k_r·I_r + k_t·I_t
// down to ray.depth, pruned below ray.minContribution.
#include <cstdint>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "pipeline/frame_inputs.h"
#include "ray/camera_rays.h"
#include "ray/sampling.h"
#include "ray/traced_scene.h"

namespace facet::ray {

// The frame's ray tree, counted (each worker its own, then summed).
struct RayStatistics {
  std::uint64_t primary = 0, shadow = 0, reflected = 0, transmitted = 0;
  std::uint64_t totalInternal = 0;        // transmissions turned into reflections
  std::uint64_t continued = 0;            // rays going on past a blended surface
  std::uint64_t stoppedByDepth = 0;       // reflected or transmitted rays not traced at ray.depth
  std::uint64_t stoppedByContribution = 0;  // nor below ray.minContribution
  std::uint64_t depthSum = 0;             // over every primary, reflected and transmitted ray: its level (primary: 1)
  int maxDepth = 0;

  void add(const RayStatistics& other);
  // "ray tree: 480000 primary, 912000 shadow, 12000 reflected, ...; depth mean 1.03, max 5; ..."
  std::string summary() const;
};

// A shadow ray's view of the scene, for the fragment stage's S
// (shading/lighting.h: illuminate calls shadowFactorLanes with it).
struct TracedShadows {
  const class RayTracer* tracer = nullptr;
  glm::vec3 geometricNormal{0.0f};  // of the surface the shadow rays leave (the offset's direction)
  RayStatistics* statistics = nullptr;
  PathSampler* sampler = nullptr;   // the path's numbers: a point of an area light
};

// S of a light at P: 0 behind an opaque surface, the product of the
// transmissive surfaces' k_t it crosses, 1 for none; 1 for a light whose
// shadows are off.
float shadowFactorLanes(const TracedShadows& shadows, const FrameLight& light, const ShadowSettings& settings, glm::vec3 P, glm::vec3 N,
                        glm::vec3 L, bool active);

class RayTracer {
 public:
  RayTracer(const TracedScene& scene, const FrameInputs& frame);

  // Pixel (px, py) seen at `offset` from its centre by one path: its linear
  // colour and α, as the colour buffer holds them (straight). The path's
  // sampler places it on the lens and the lights and spreads its gloss.
  glm::vec4 pixel(int px, int py, glm::vec2 offset, PathSampler& sampler, RayStatistics& statistics) const;

  // The triangle the pixel's primary ray keeps: 0 for none, else 1 + its
  // index in the frame (FrameOutput::TriangleIds); a blended surface keeps none.
  std::uint32_t visibleTriangle(int px, int py) const;
  // How many surfaces the pixel's primary ray crosses between N and F, the culled ones left out (depth complexity).
  std::uint32_t surfacesCrossed(int px, int py) const;

  // The eye depth in focus: camera.focusDistance, or where it is 0 (autofocus)
  // the depth the image's centre ray meets a surface at, else the reference point's.
  float focus() const { return focus_; }

  // S of `light` at P for a shadow ray leaving a surface of geometric normal
  // Ng: toward the light's centre, or a point of its area drawn by `sampler`.
  float shadowFactor(const FrameLight& light, glm::vec3 P, glm::vec3 Ng, PathSampler& sampler, RayStatistics& statistics) const;

 private:
  struct Path;
  glm::vec4 trace(const Ray& ray, const Path& path, RayStatistics& statistics) const;
  // The nearest hit the ray can see: culled back faces (primary rays) and what a mask discards let it
  // through, and blended surfaces too where they keep nothing (the visible triangle of a pixel).
  bool nearestHit(const Ray& ray, bool primary, Hit& hit, bool throughBlended = false) const;
  // A ray from P to `direction`, moved ε·R along Ng to the side it goes.
  Ray leaving(glm::vec3 P, glm::vec3 Ng, glm::vec3 direction) const;

  const TracedScene& scene_;
  const FrameInputs& frame_;
  CameraRays camera_;
  float offset_;  // ε·R
  float focus_;
};

}  // namespace facet::ray
