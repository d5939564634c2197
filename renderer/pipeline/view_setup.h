#pragma once
// Turning `auto` camera and lights into concrete values for a scene. Shared by
// every backend, the command line and the viewer.
#include <vector>

#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

// The camera a frame uses, with source = manual: the settings' own values
// (manual), the scene's first camera, or one that frames the scene's
// bounding sphere from the front right, above (auto).
CameraSettings resolveCamera(const Scene& scene, const RenderSettings& settings);

// The lights a frame uses: the settings' list (manual), the scene's lights,
// or one shadow-casting point light above the front left of the scene (auto).
std::vector<Light> resolveLights(const Scene& scene, const RenderSettings& settings);

// A copy of settings with the camera and/or the lights resolved and switched
// to manual, so that editing them starts from what auto chose.
RenderSettings materialize(const Scene& scene, const RenderSettings& settings, bool camera, bool lights);

// Bounding sphere used for auto cameras, lights and light frusta: the scene's
// world bounds, or the unit sphere for an empty scene.
struct Sphere {
  glm::vec3 center{0.0f};
  float radius = 1.0f;
};
Sphere sceneSphere(const Scene& scene);

}  // namespace facet
