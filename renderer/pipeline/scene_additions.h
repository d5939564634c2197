#pragma once
// What the settings add to a scene before a frame is built from it
// (renderer/PIPELINE.md, "Volume rendering" and "Particle systems"): the volume, as marching
// cubes' iso-surface, as splats, or as the box ray casting fills; and the
// particles of every emitter at settings.time, as sprites.
#include <cstdint>
#include <memory>
#include <string>

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

// The steps of the frame's spine (pipeline/frame_spine.h), each on a scene
// the spine made, never on the loaded one.

// The volume `file` names, read at `settings.resolution` (the builtin's
// samples a side). Throws facet::Error naming the key or the file.
Volume readVolume(const VolumeSettings& settings, const std::string& file);

// Places `volume` in `scene` as `settings` say: marching cubes' iso-surface
// as a mesh, or the box that ray casting or splats fill counted in its
// bounds. Throws facet::Error naming the key (volume.transfer).
void placeVolume(Scene& scene, std::shared_ptr<const Volume> volume, const VolumeSettings& settings, SceneAdditions& added);

// Whether the frame adds sprites (particles, splats): they face the camera
// they were added for, so each frame adds its own.
bool addsSprites(const Scene& scene, const RenderSettings& settings);

// The splats of the volume `scene` holds (volume.mode = splat) and the
// particles of every emitter at settings.time, added to `scene` as sprites
// facing `camera`. Throws facet::Error naming the key or file at fault;
// `threads` runs the particles' integration (0: one per core).
void addSplatsAndParticles(Scene& scene, const RenderSettings& settings, const CameraSettings& camera, SceneAdditions& added, int threads);

}  // namespace facet
