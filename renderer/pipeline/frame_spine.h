#pragma once
// The spine of every frame (renderer/PIPELINE.md, "One source of truth"): the loaded
// scene, the settings asked, the camera's move and the time (settings.time)
// in; everything the frame is drawn from out. What the settings add goes
// into scenes the spine makes, never into the loaded one: the material maps
// (displacement, bump map, environment map; pipeline/displacement.h,
// pipeline/bump_map.h, scene/environment_map.h), the volume as marching
// cubes' iso-surface or as the box ray casting or splats fill, and the
// sprites of splats and particles, facing the frame's camera
// (pipeline/scene_additions.h). `facet render`, `info`, `bench`, `batch`,
// the viewer and the agreement suite all draw from it.
#include <memory>
#include <string>
#include <vector>

#include "image/image.h"
#include "pipeline/camera_orbit.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/scene_additions.h"
#include "scene/scene.h"
#include "scene/volume.h"
#include "settings/render_settings.h"

namespace facet {

// The scene a frame draws and the settings it is built with.
struct FrameScene {
  // The loaded scene itself when the settings add nothing; else one the
  // spine made: the loaded scene with the material maps, the volume and the
  // sprites. Frames that add the same without sprites share one (a GL
  // backend uploads it once); sprites make a scene for each frame.
  std::shared_ptr<const Scene> scene;
  // The settings asked, the camera moved by the orbit (then manual); where
  // sprites are added, the camera and lights resolved first (on the scene
  // and its volume's box, not the sprites) and made manual, so that the
  // sprites face the frame's camera.
  RenderSettings settings;
  SceneAdditions added;
};

// Everything a frame is drawn from: its scene and settings, then the inputs
// built from them.
struct PreparedFrame : FrameScene {
  FrameInputs inputs;                 // buildFrameInputs(*scene, settings); points into *scene
  std::vector<std::string> warnings;  // the scene's (the loader's, the maps', the volume's), then the inputs'
};

// The file of one kind a spine read last and what it held: read again only for another name.
template <class T>
class LastRead {
 public:
  template <class Read>
  const std::shared_ptr<const T>& get(const std::string& name, Read&& read) {
    if (!value_ || name_ != name) {
      value_ = std::make_shared<const T>(read(name));
      name_ = name;
    }
    return value_;
  }

 private:
  std::string name_;
  std::shared_ptr<const T> value_;
};

class FrameSpine {
 public:
  // `loaded`: the scene as read, never changed. `threads`: the particles'
  // integration (0: one per core).
  explicit FrameSpine(std::shared_ptr<const Scene> loaded, int threads = 0);

  const std::shared_ptr<const Scene>& loaded() const { return loaded_; }
  // Frames of another loaded scene from now on; the files read stay.
  void setLoaded(std::shared_ptr<const Scene> loaded);

  // The frame of `asked` at its time (asked.time: the animation's and the
  // particles'), its camera moved by `orbit` from where `asked` puts it
  // (about the scene with its volume, whose box an auto camera frames). Throws facet::Error naming the key or file at fault, in the
  // order of the steps: the displacement map, the bump map, the environment
  // map, the volume, the sprites, then the frame's inputs.
  PreparedFrame frame(const RenderSettings& asked, const CameraOrbit& orbit = {});
  // The same without the inputs: what `facet info` describes and `facet bench` times.
  FrameScene scene(const RenderSettings& asked, const CameraOrbit& orbit = {});

  // The next frame makes its scenes anew from the files already read: what `facet bench` times.
  void forgetScenes();

 private:
  // The loaded scene with the material maps `asked` names (the loaded one itself for none).
  std::shared_ptr<const Scene> withMaps(const RenderSettings& asked);
  // `base` with the volume `settings` or the scene names placed in it (`base` itself for none).
  std::shared_ptr<const Scene> withVolume(const std::shared_ptr<const Scene>& base, const VolumeSettings& settings, SceneAdditions& added);

  std::shared_ptr<const Scene> loaded_;
  int threads_;
  // The files read: the last of each kind.
  LastRead<Image> displacementMap_, bumpMap_;
  LastRead<EnvironmentMap> environment_;
  LastRead<Volume> volume_;  // by file@resolution
  // The scenes made, the last of each, and what they were made from.
  std::string mapsKey_;
  std::shared_ptr<const Scene> withMaps_;
  std::shared_ptr<const Scene> volumeBase_;
  VolumeSettings volumeSettings_;
  SceneAdditions volumeAdded_;
  std::shared_ptr<const Scene> withVolume_;
};

}  // namespace facet
