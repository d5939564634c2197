#include "pipeline/view_setup.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "math/elementary.h"

namespace facet {

Sphere sceneSphere(const Scene& scene) {
  const Bounds bounds = scene.worldBounds();
  Sphere sphere;
  if (!bounds.empty && std::isfinite(bounds.radius())) {
    sphere.center = bounds.center();
    sphere.radius = std::max(bounds.radius(), 1e-4f);
  }
  return sphere;
}

namespace {

// Near and far planes that hold the sphere seen from `eye` along `forward`.
void fitDepthRange(const Sphere& sphere, glm::vec3 eye, glm::vec3 forward, float& near, float& far) {
  const float along = glm::dot(sphere.center - eye, forward);
  far = std::max(along + 1.05f * sphere.radius, 1e-3f);
  near = std::max(along - 1.05f * sphere.radius, far * 1e-3f);
}

}  // namespace

CameraSettings resolveCamera(const Scene& scene, const RenderSettings& settings) {
  CameraSettings camera = settings.camera;
  camera.source = Source::Manual;
  if (settings.camera.source == Source::Manual) return camera;
  const float aspect = static_cast<float>(settings.width) / static_cast<float>(settings.height);
  const Sphere sphere = sceneSphere(scene);

  if (!scene.cameras.empty()) {
    const SceneCamera& c = scene.cameras.front();
    camera.eye = c.eye;
    camera.reference = c.reference;
    camera.up = c.up;
    camera.projection = c.projection;
    if (c.projection == ProjectionKind::Perspective) {
      // The course's θ is horizontal: tan θ = A_R · tan(yfov / 2).
      camera.halfAngleDeg = std::clamp(glm::degrees(elementary::atan(aspect * elementary::tan(0.5f * c.yfov))), 0.5f, 89.5f);
    } else {
      camera.parallelWidth = 2.0f * c.ymag * aspect;  // keep the file's vertical extent
    }
    camera.near = c.near;
    if (c.far) {
      camera.far = *c.far;
    } else {
      float fittedNear = 0;
      fitDepthRange(sphere, c.eye, glm::normalize(c.reference - c.eye), fittedNear, camera.far);
      camera.far = std::max(camera.far, 2.0f * camera.near);
    }
    return camera;
  }

  // Frame the bounding sphere: far enough that it fits both across and up.
  const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, 0.8f, 1.6f));
  float distance = 0;
  if (camera.projection == ProjectionKind::Perspective) {
    const float tanTheta = elementary::tan(glm::radians(camera.halfAngleDeg));
    const float halfAngle = std::min(elementary::atan(tanTheta), elementary::atan(tanTheta / aspect));
    distance = 1.1f * sphere.radius / std::sin(halfAngle);
  } else {
    camera.parallelWidth = 2.2f * sphere.radius * std::max(1.0f, aspect);
    distance = 3.0f * sphere.radius;
  }
  camera.eye = sphere.center + distance * direction;
  camera.reference = sphere.center;
  camera.up = {0.0f, 1.0f, 0.0f};
  fitDepthRange(sphere, camera.eye, -direction, camera.near, camera.far);
  return camera;
}

std::vector<Light> resolveLights(const Scene& scene, const RenderSettings& settings) {
  if (settings.lightSource == Source::Manual) return settings.lights;
  if (!scene.lights.empty()) return scene.lights;
  const Sphere sphere = sceneSphere(scene);
  Light key;
  key.kind = LightKind::Point;
  key.position = sphere.center + 3.0f * sphere.radius * glm::normalize(glm::vec3(-1.0f, 2.0f, 1.5f));
  key.direction = glm::normalize(sphere.center - key.position);
  key.attenuation = {1.0f, 0.0f, 0.0f};
  key.castsShadow = true;
  return {key};
}

RenderSettings materialize(const Scene& scene, const RenderSettings& settings, bool camera, bool lights) {
  RenderSettings out = settings;
  if (camera) out.camera = resolveCamera(scene, settings);
  if (lights) {
    out.lights = resolveLights(scene, settings);
    if (out.lights.size() > kMaxLights) out.lights.resize(kMaxLights);  // what the frame shows (buildFrameInputs)
    out.lightSource = Source::Manual;
  }
  return out;
}

}  // namespace facet
