#pragma once
// What the settings add to a scene before a frame is built from it
// (renderer/PIPELINE.md, sections 11 and 12): the volume, as marching
// cubes' iso-surface, as splats, or as the box ray casting fills; and the
// particles of every emitter at settings.time, as sprites.
#include <cstdint>

#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

struct SceneAdditions {
  std::uint64_t particles = 0;     // sprites of particles added
  std::uint64_t splats = 0;        // sprites of voxels added
  std::uint64_t isoTriangles = 0;  // marching cubes' triangles added
  bool isosurface = false;         // the volume was drawn as marching cubes' iso-surface
  bool rayCastVolume = false;      // scene.volume is ray cast by the frame
};

// The volume's model space to world: scaled by size / (the box's longest
// side), turned by `rotation` about the box's centre, which is moved to `center`.
glm::mat4 worldFromVolume(const Volume& volume, const VolumeSettings& settings);

// Adds what the settings ask for to `scene` and returns the settings the
// frame is built with: when sprites are added, the camera and lights
// resolved first (on the scene and its volume's box, not the particles)
// and switched to manual, so that the sprites face the frame's camera.
// Throws facet::Error naming the key or file at fault; `threads` runs the
// particles' integration (0: one per core).
RenderSettings addVolumeAndParticles(Scene& scene, const RenderSettings& settings, SceneAdditions& added, int threads = 0);

// Whether addVolumeAndParticles adds sprites (particles, splats): they face
// the camera they were added for, so a frame from another camera adds them
// anew to the scene as it was before.
bool addsSprites(const Scene& scene, const RenderSettings& settings);

}  // namespace facet
