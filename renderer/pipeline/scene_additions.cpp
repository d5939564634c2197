// The volume and the particles the settings add to a scene.
#include "pipeline/scene_additions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include "common/error.h"
#include "image/png.h"
#include "particles/particle_system.h"
#include "particles/sprites.h"
#include "pipeline/view_setup.h"
#include "scene/memory_budget.h"
#include "volume/load_volume.h"
#include "volume/marching_cubes.h"

namespace facet {
namespace {

// The side of the splats' footprint texture, in texels.
constexpr int kFootprintSide = 64;

// The course's precomputed footprint, reused for every voxel: a Gaussian of
// σ = radius/3 over the square [−radius, radius]², as alpha on white.
Image gaussianFootprint() {
  Image image(kFootprintSide, kFootprintSide);
  const float half = 0.5f * static_cast<float>(kFootprintSide);
  for (int y = 0; y < kFootprintSide; ++y)
    for (int x = 0; x < kFootprintSide; ++x) {
      // (dx, dy) in units of the radius; r/σ = 3·|(dx, dy)|.
      const float dx = (static_cast<float>(x) + 0.5f - half) / half, dy = (static_cast<float>(y) + 0.5f - half) / half;
      const float a = std::exp(-4.5f * (dx * dx + dy * dy));
      image.at(x, y) = {255, 255, 255, static_cast<std::uint8_t>(a * 255.0f + 0.5f)};
    }
  return image;
}

// The mean of the finite samples: the default iso value, which separates a
// scan's tissue from its background far better than the middle of the range
// (one bright voxel moves that), and is 0.5 for the Marschner-Lobb signal.
float meanValue(const Volume& volume) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const float v : volume.values)
    if (std::isfinite(v)) sum += v, ++count;
  return count ? static_cast<float>(sum / static_cast<double>(count)) : 0.0f;
}

void addIsosurface(Scene& scene, const VolumeSettings& settings, SceneAdditions& added) {
  const Volume& volume = *scene.volume.data;
  const float iso = settings.isoValue ? *settings.isoValue : meanValue(volume);
  if (!(iso >= volume.minValue && iso <= volume.maxValue))
    scene.warnings.push_back("volume.isoValue " + std::to_string(iso) + " is outside the data's range [" + std::to_string(volume.minValue) + ", " +
                             std::to_string(volume.maxValue) + "]: the iso-surface is empty");
  Mesh mesh = marchingCubes(volume, iso);
  added.isosurface = true;
  added.isoTriangles = mesh.triangleCount();
  if (mesh.indices.empty()) return;
  mesh.name = "isosurface";
  const int material = scene.addMaterial("isosurface", settings.isoColor, 0.0f, 0.5f);
  scene.materials[static_cast<std::size_t>(material)].doubleSided = true;  // an open surface at the box's walls shows its inside
  scene.addObject(std::move(mesh), material, scene.volume.worldFromVolume);
}

// One sprite per voxel the transfer function does not make transparent, of
// its colour and opacity, 2·radius voxel spacings across.
std::vector<Sprite> splats(const Scene& scene, const VolumeSettings& settings) {
  const Volume& volume = *scene.volume.data;
  const TransferFunction& transfer = scene.volume.transfer;
  std::uint64_t visible = 0;
  for (const float value : volume.values) visible += transfer(value).a > 0.0f ? 1 : 0;
  const std::uint64_t most = kFrameMemoryBudget / instanceFrameBytes(4, 2);
  if (visible > most)
    throw Error("settings key 'volume.mode': splat: " + std::to_string(visible) + " voxels are visible under volume.transfer, more than the " +
                std::to_string(most) + " splats the frame budget of " + byteCount(kFrameMemoryBudget) + " holds");
  const glm::mat4& world = scene.volume.worldFromVolume;
  const float scale = glm::length(glm::vec3(world[0]));
  const float spacing = scale * std::max({volume.spacing.x, volume.spacing.y, volume.spacing.z});
  std::vector<Sprite> out;
  out.reserve(visible);
  for (int z = 0; z < volume.size.z; ++z)
    for (int y = 0; y < volume.size.y; ++y)
      for (int x = 0; x < volume.size.x; ++x) {
        const glm::vec4 c = transfer(volume.at(x, y, z));
        if (!(c.a > 0.0f)) continue;
        const glm::vec3 p = glm::vec3(x, y, z) * volume.spacing;
        out.push_back({glm::vec3(world * glm::vec4(p, 1.0f)), 2.0f * settings.splatRadius * spacing, c});
      }
  return out;
}

// Every emitter's particles at `time`: the scene's, then the settings'.
std::uint64_t addParticles(Scene& scene, const RenderSettings& settings, const CameraSettings& camera, int threads) {
  struct Source {
    const Emitter* emitter;
    std::string key;
  };
  std::vector<Source> sources;
  const std::vector<Emitter> fromScene = scene.emitters;
  for (std::size_t i = 0; i < fromScene.size(); ++i) sources.push_back({&fromScene[i], "scene emitter " + std::to_string(i)});
  for (std::size_t i = 0; i < settings.particles.size(); ++i) sources.push_back({&settings.particles[i], "particles." + std::to_string(i)});
  // The budget over every emitter, counted before anything is simulated.
  std::uint64_t alive = 0;
  for (const Source& s : sources) {
    alive += aliveParticleCount(*s.emitter, settings.time);
    if (alive > kMaxParticles) {
      char time[32];
      std::snprintf(time, sizeof time, "%g", static_cast<double>(settings.time));
      throw Error("settings key '" + s.key + ".rate': " + std::to_string(alive) + " particles alive at time " + time +
                  " s over the emitters so far, more than the " + std::to_string(kMaxParticles) + " a frame holds");
    }
  }
  std::uint64_t added = 0;
  for (const Source& s : sources) {
    const std::vector<Particle> particles = simulateParticles(*s.emitter, settings.time, s.emitter->step, s.key.c_str(), threads);
    std::vector<Sprite> sprites;
    sprites.reserve(particles.size());
    for (const Particle& p : particles) sprites.push_back({p.position, p.size, p.color});
    const Image sprite = s.emitter->sprite.empty() ? softDisc(64) : readPng(s.emitter->sprite);
    addSprites(scene, sprites, camera, sprite, s.emitter->blending, s.emitter->castsShadow, "particles of " + s.key);
    added += sprites.size();
  }
  return added;
}

}  // namespace

glm::mat4 worldFromVolume(const Volume& volume, const VolumeSettings& settings) {
  const glm::vec3 extent = volume.extent();
  const float longest = std::max({extent.x, extent.y, extent.z});
  const float scale = longest > 0.0f ? settings.size / longest : 1.0f;
  const glm::vec3 r = glm::radians(settings.rotation);
  const glm::mat4 rotation = glm::rotate(glm::mat4(1.0f), r.z, glm::vec3(0, 0, 1)) * glm::rotate(glm::mat4(1.0f), r.y, glm::vec3(0, 1, 0)) *
                             glm::rotate(glm::mat4(1.0f), r.x, glm::vec3(1, 0, 0));
  return glm::translate(glm::mat4(1.0f), settings.center) * rotation * glm::scale(glm::mat4(1.0f), glm::vec3(scale)) *
         glm::translate(glm::mat4(1.0f), -0.5f * extent);
}

Volume readVolume(const VolumeSettings& settings, const std::string& file) {
  if (settings.resolution < kMinMarschnerLobbResolution || settings.resolution > kMaxMarschnerLobbResolution)
    throw Error("settings key 'volume.resolution': " + std::to_string(settings.resolution) + " is outside " +
                std::to_string(kMinMarschnerLobbResolution) + " to " + std::to_string(kMaxMarschnerLobbResolution));
  return loadVolume(file, settings.resolution);
}

void placeVolume(Scene& scene, std::shared_ptr<const Volume> volume, const VolumeSettings& settings, SceneAdditions& added) {
  scene.volume.data = std::move(volume);
  scene.volume.worldFromVolume = worldFromVolume(*scene.volume.data, settings);
  scene.volume.transfer = parseTransferFunction(settings.transfer, scene.volume.data->minValue, scene.volume.data->maxValue);
  if (settings.mode == VolumeMode::Isosurface) {
    addIsosurface(scene, settings, added);
    return;
  }
  const glm::vec3 extent = scene.volume.data->extent();
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? extent.x : 0.0f, (corner & 2) ? extent.y : 0.0f, (corner & 4) ? extent.z : 0.0f);
    scene.unmeshed.include(glm::vec3(scene.volume.worldFromVolume * glm::vec4(p, 1.0f)));
  }
  scene.identity.renew();
  added.rayCastVolume = settings.mode == VolumeMode::Raycast;
}

bool addsSprites(const Scene& scene, const RenderSettings& settings) {
  const bool volume = !settings.volume.file.empty() || !scene.volume.file.empty();
  return !settings.particles.empty() || !scene.emitters.empty() || (volume && settings.volume.mode == VolumeMode::Splat);
}

void addSplatsAndParticles(Scene& scene, const RenderSettings& settings, const CameraSettings& camera, SceneAdditions& added, int threads) {
  if (scene.volume.data && settings.volume.mode == VolumeMode::Splat) {
    const std::vector<Sprite> voxels = splats(scene, settings.volume);
    addSprites(scene, voxels, camera, gaussianFootprint(), SpriteBlending::Over, true, "splats");
    added.splats = voxels.size();
  }
  added.particles = addParticles(scene, settings, camera, threads);
}

}  // namespace facet
