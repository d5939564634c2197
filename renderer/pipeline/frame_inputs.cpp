#include "pipeline/frame_inputs.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "common/error.h"
#include "math/eye_matrix.h"
#include "math/normal_matrix.h"
#include "math/projection.h"
#include "math/viewport.h"
#include "pipeline/antialiasing.h"
#include "pipeline/displacement.h"
#include "pipeline/frame_checks.h"
#include "pipeline/material_coefficients.h"
#include "pipeline/painters_order.h"
#include "pipeline/transparency_order.h"
#include "pipeline/texture_filter.h"
#include "pipeline/view_setup.h"

namespace facet {

std::vector<std::size_t> firstTriangles(const Scene& scene, const FrameInputs& frame) {
  std::vector<std::size_t> first{0};
  for (const FrameInstance& instance : frame.instances)
    first.push_back(first.back() + scene.meshes[static_cast<std::size_t>(instance.mesh)].triangleCount());
  return first;
}

std::size_t instanceOfTriangle(const std::vector<std::size_t>& first, std::size_t triangle) {
  return static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), triangle) - first.begin()) - 1;
}

void placeInstances(const Scene& scene, float time, FrameInputs& f) {
  std::vector<glm::mat4> transforms(scene.instances.size());
  for (std::size_t i = 0; i < transforms.size(); ++i) transforms[i] = scene.instances[i].worldFromModel;
  if (!scene.animation.empty()) transforms = instanceTransformsAt(scene.animation, transforms, time);
  for (std::size_t i = 0; i < f.instances.size() && i < transforms.size(); ++i) {
    FrameInstance& fi = f.instances[i];
    fi.worldFromModel = transforms[i];
    fi.normalMatrix = normalMatrix(transforms[i]);
    fi.clipFromModel = f.clipFromWorld * transforms[i];
  }
}

FrameInputs buildFrameInputs(const Scene& scene, const RenderSettings& settings) {
  for (std::size_t i = 0; i < scene.instances.size(); ++i)  // read below, before checkFrame
    if (scene.instances[i].mesh < 0 || static_cast<std::size_t>(scene.instances[i].mesh) >= scene.meshes.size())
      throw Error("instance " + std::to_string(i) + ": mesh " + std::to_string(scene.instances[i].mesh) + " does not exist (the scene has " +
                  std::to_string(scene.meshes.size()) + ")");
  if (settings.lightSource == Source::Manual && settings.lights.size() > kMaxLights)
    throw Error("settings key 'lights': " + std::to_string(settings.lights.size()) + " lights, a frame shades at most " +
                std::to_string(kMaxLights));
  FrameInputs f;
  if (settings.volume.mode == VolumeMode::Raycast && scene.volume.data)
    f.volume = {&scene.volume, settings.volume.step, settings.volume.earlyTermination, settings.volume.emptySpaceSkipping};
  f.width = settings.width;
  f.height = settings.height;
  f.camera = resolveCamera(scene, settings);
  const CameraSettings& c = f.camera;
  checkEyeFrame(c);
  if (!(c.near > 0.0f) || !(c.far > c.near)) throw Error("settings key 'camera.far': must be greater than camera.near > 0");

  const float aspect = static_cast<float>(f.width) / static_cast<float>(f.height);
  f.eyePosition = c.eye;
  f.towardEye = -glm::normalize(c.reference - c.eye);
  f.perspective = c.projection == ProjectionKind::Perspective;
  f.eyeFromWorld = eyeMatrix(c.eye, c.reference, c.up);
  f.clipFromEye = f.perspective ? perspective(glm::radians(c.halfAngleDeg), aspect, c.near, c.far)
                                : parallel(c.parallelWidth, c.parallelWidth / aspect, c.near, c.far);
  f.clipFromWorld = f.clipFromEye * f.eyeFromWorld;
  f.windowFromNdc = viewportMatrix(f.width, f.height);

  if (displacementKey(settings.material) != scene.displacement)
    throw Error("material.displacementMap: the scene's meshes were not displaced with these settings (FrameSpine displaces them)");
  if (settings.material.bumpMap != scene.bumpMapPath)
    throw Error("material.bumpMap: '" + settings.material.bumpMap + "' is not the scene's loaded bump map (FrameSpine loads it)");
  if (!scene.bumpMapPath.empty() && interpolatesNormals(settings.shading)) {
    f.bump.map = &scene.bumpMap;
    f.bump.scale = settings.material.bumpScale;
  }
  if (settings.environment.map != scene.environment.path)
    throw Error("environment.map: '" + settings.environment.map + "' is not the scene's loaded map (FrameSpine loads it)");
  if (!scene.environment.empty()) {
    FrameInputs::Environment& e = f.environment;
    e.map = &scene.environment;
    e.reflectivity = settings.environment.reflectivity;
    e.background = settings.environment.background;
    // The view rays through NDC (x, y), from the inverse of the course's PM·EM (in double): at a
    // fixed NDC depth, a ray's world point minus the eye is linear in x and y.
    const glm::dmat4 worldFromClip = glm::inverse(glm::dmat4(f.clipFromWorld));
    const auto at = [&](double x, double y, double z) {
      const glm::dvec4 p = worldFromClip * glm::dvec4(x, y, z, 1.0);
      return glm::dvec3(p) / p.w;
    };
    if (f.perspective) {
      const glm::dvec3 eye(c.eye), centre = at(0, 0, 0.5) - eye;
      const double scale = 1.0 / glm::length(centre);  // F of unit length, X and Y to match
      e.forward = glm::vec3(centre * scale);
      e.right = glm::vec3((at(1, 0, 0.5) - at(0, 0, 0.5)) * scale);
      e.up = glm::vec3((at(0, 1, 0.5) - at(0, 0, 0.5)) * scale);
    } else {
      e.forward = glm::vec3(glm::normalize(at(0, 0, 1) - at(0, 0, 0)));
    }
  }

  for (const Material& m : scene.materials) {
    CourseMaterial course = courseMaterial(m, settings.material, settings.transparency);
    if (course.baseColorTexture >= 0 && static_cast<std::size_t>(course.baseColorTexture) < scene.textures.size())  // else refused by checkFrame
      course.baseColorSampler = filteredSampler(scene.textures[static_cast<std::size_t>(course.baseColorTexture)].sampler, settings.textures.filter);
    for (MaterialMap* map : {&course.metallicRoughnessMap, &course.occlusionMap, &course.emissiveMap, &course.normalMap})
      if (map->texture >= 0 && static_cast<std::size_t>(map->texture) < scene.textures.size())
        map->sampler = filteredSampler(scene.textures[static_cast<std::size_t>(map->texture)].sampler, settings.textures.filter),
        map->srgb = scene.textures[static_cast<std::size_t>(map->texture)].encoding == TexelEncoding::Srgb;
    f.materials.push_back(course);
  }
  f.materials.push_back(courseMaterial(Material{}, settings.material, settings.transparency));  // glTF's default material
  const int defaultMaterial = static_cast<int>(f.materials.size() - 1);

  f.instances.reserve(scene.instances.size());
  for (const MeshInstance& instance : scene.instances) {
    FrameInstance fi;
    fi.mesh = instance.mesh;
    const int material = scene.meshes[static_cast<std::size_t>(instance.mesh)].material;
    fi.material = material >= 0 && material < defaultMaterial ? material : defaultMaterial;
    fi.cullBackFaces = settings.cullBackFaces && !f.materials[static_cast<std::size_t>(fi.material)].doubleSided;
    f.instances.push_back(fi);
  }
  f.time = settings.time;
  placeInstances(scene, f.time, f);

  // Shadow-map window coordinates: [-1,1]² of the light's NDC onto [0,1]².
  const glm::mat4 shadowWindowFromNdc = windowToViewport({-1, 1, -1, 1}, {0, 1, 0, 1});
  const Sphere sphere = sceneSphere(scene);
  std::vector<Light> lights = resolveLights(scene, settings);
  if (lights.size() > kMaxLights) {
    f.warnings.push_back("the scene has " + std::to_string(lights.size()) + " lights; a frame shades the first " + std::to_string(kMaxLights));
    lights.resize(kMaxLights);
  }
  for (const Light& light : lights) {
    FrameLight fl;
    fl.light = light;
    if (light.kind != LightKind::Point) fl.light.direction = glm::normalize(light.direction);
    if (light.kind == LightKind::Spot) fl.cosCutoff = std::cos(glm::radians(light.spotCutoffDeg));
    fl.intensity = light.color * light.intensity;
    fl.hasShadowMap = settings.shadows.enabled && light.castsShadow;
    if (fl.hasShadowMap) {
      fl.frustum = lightFrustum(fl.light, sphere);
      fl.shadowLayer = f.shadowLayerCount;
      f.shadowLayerCount += fl.frustum.faceCount;
      for (int face = 0; face < fl.frustum.faceCount; ++face)
        fl.shadowFromWorld[static_cast<std::size_t>(face)] = shadowWindowFromNdc * fl.frustum.clipFromWorld[static_cast<std::size_t>(face)];
    }
    f.lights.push_back(fl);
  }

  f.ambient = settings.ambient;
  f.shading = settings.shading;
  f.procedural = settings.material.procedural;
  f.fog = {settings.fog.mode, settings.fog.color, settings.fog.start, settings.fog.end, settings.fog.density,
           static_cast<float>(1.0 / std::tan(static_cast<double>(glm::radians(f.camera.halfAngleDeg))))};
  f.proceduralScale = settings.material.proceduralScale;
  f.specular = settings.specular;
  f.cullBackFaces = settings.cullBackFaces;
  f.hsr = settings.hsr;
  if (f.hsr == HiddenSurface::Painter) f.paintersOrder = paintersOrder(scene, f);
  f.blending = settings.blending;
  f.areaAveraged = settings.antialiasing.pattern == SamplePattern::Area;
  if (settings.antialiasing.samples > 1 && !f.areaAveraged)
    f.samples = sampleOffsets(samplesPerSide(settings.antialiasing.samples), settings.antialiasing.pattern,
                              static_cast<unsigned>(settings.antialiasing.seed));
  const bool anyBlended = std::any_of(f.instances.begin(), f.instances.end(),
                                      [&](const FrameInstance& i) { return f.materials[static_cast<std::size_t>(i.material)].blended; });
  if (anyBlended && f.hsr == HiddenSurface::Painter) {
    // The painter's algorithm keeps no depth to test blended fragments against after the opaque ones.
    f.warnings.push_back("hsr " + std::string(kHiddenSurfaceNames[static_cast<std::size_t>(f.hsr)]) +
                         ": blended materials are drawn opaque (transparency is drawn with hsr zbuffer)");
    for (CourseMaterial& material : f.materials) material.blended = false;
  } else if (anyBlended) {
    f.transparentOrder = transparentOrder(scene, f, settings.transparency.sort);
  }
  f.shadows = settings.shadows;
  f.background = settings.background;
  f.ray = settings.ray;
  const Bounds bounds = scene.worldBounds();
  f.sceneRadius = bounds.empty || !(bounds.radius() > 0.0f) ? 1.0f : bounds.radius();
  f.backgroundAlpha = settings.backgroundAlpha;
  checkFrame(scene, f);
  return f;
}

}  // namespace facet
