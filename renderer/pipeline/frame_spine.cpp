// The spine: the loaded scene and the settings in, the frame's scene, settings and inputs out.
#include "pipeline/frame_spine.h"

#include <utility>

#include "common/error.h"
#include "pipeline/bump_map.h"
#include "pipeline/displacement.h"
#include "pipeline/view_setup.h"
#include "scene/environment_map.h"

namespace facet {
namespace {

// Runs `step`; a facet::Error from it is named by the settings key `key`
// ("material.bumpMap: bumps.png: ..."), unless it names a key starting with
// `named` already ("material.displacementSubdivisions: ...").
template <class Step>
void underKey(const std::string& key, const std::string& named, Step&& step) {
  try {
    step();
  } catch (const Error& e) {
    const std::string what = e.what();
    throw Error(!named.empty() && what.rfind(named, 0) == 0 ? what : key + ": " + what);
  }
}

}  // namespace

FrameSpine::FrameSpine(std::shared_ptr<const Scene> loaded, int threads) : loaded_(std::move(loaded)), threads_(threads) {}

void FrameSpine::setLoaded(std::shared_ptr<const Scene> loaded) {
  loaded_ = std::move(loaded);
  forgetScenes();
}

void FrameSpine::forgetScenes() {
  mapsKey_.clear();
  withMaps_.reset();
  volumeBase_.reset();
  withVolume_.reset();
}

std::shared_ptr<const Scene> FrameSpine::withMaps(const RenderSettings& asked) {
  const MaterialOverrides& material = asked.material;
  if (material.displacementMap.empty() && material.bumpMap.empty() && asked.environment.map.empty()) return loaded_;
  const std::string key = displacementKey(material) + '\n' + material.bumpMap + '\n' + asked.environment.map;
  if (withMaps_ && mapsKey_ == key) return withMaps_;
  auto scene = std::make_shared<Scene>(*loaded_);
  if (!material.displacementMap.empty()) {
    underKey("material.displacementMap", "material.", [&] {
      const Image& heights = *displacementMap_.get(material.displacementMap, loadHeightMap);
      displaceMeshes(*scene, heights, material.displacementScale, material.displacementSubdivisions);
    });
    scene->displacement = displacementKey(material);
  }
  if (!material.bumpMap.empty())
    underKey("material.bumpMap", "material.", [&] { useBumpMap(*scene, material.bumpMap, *bumpMap_.get(material.bumpMap, loadHeightMap)); });
  if (!asked.environment.map.empty())
    underKey("environment.map", "", [&] { scene->environment = *environment_.get(asked.environment.map, loadEnvironmentMap); });
  mapsKey_ = key;
  withMaps_ = scene;
  return withMaps_;
}

std::shared_ptr<const Scene> FrameSpine::withVolume(const std::shared_ptr<const Scene>& base, const VolumeSettings& settings, SceneAdditions& added) {
  const std::string file = settings.file.empty() ? base->volume.file : settings.file;
  if (file.empty()) return base;
  if (withVolume_ && volumeBase_ == base && volumeSettings_ == settings) {
    added = volumeAdded_;
    return withVolume_;
  }
  const std::shared_ptr<const Volume>& data =
      volume_.get(file + "@" + std::to_string(settings.resolution), [&](const std::string&) { return readVolume(settings, file); });
  auto scene = std::make_shared<Scene>(*base);
  SceneAdditions placed;
  placeVolume(*scene, data, settings, placed);
  volumeBase_ = base;
  volumeSettings_ = settings;
  volumeAdded_ = placed;
  withVolume_ = scene;
  added = placed;
  return withVolume_;
}

FrameScene FrameSpine::scene(const RenderSettings& asked, const CameraOrbit& orbit) {
  FrameScene made;
  const std::shared_ptr<const Scene> placed = withVolume(withMaps(asked), asked.volume, made.added);
  made.settings = asked;
  if (orbit.moves()) made.settings.camera = orbitCamera(resolveCamera(*placed, asked), orbit);
  if (!addsSprites(*placed, asked)) {
    made.scene = placed;
    return made;
  }
  // Sprites face the frame's camera: it and the lights are resolved on the scene and its volume, then the sprites added to a scene of this frame's.
  made.settings = materialize(*placed, made.settings, true, true);
  auto scene = std::make_shared<Scene>(*placed);
  addSplatsAndParticles(*scene, made.settings, made.settings.camera, made.added, threads_);
  made.scene = std::move(scene);
  return made;
}

PreparedFrame FrameSpine::frame(const RenderSettings& asked, const CameraOrbit& orbit) {
  PreparedFrame prepared;
  static_cast<FrameScene&>(prepared) = scene(asked, orbit);
  prepared.inputs = buildFrameInputs(*prepared.scene, prepared.settings);
  prepared.warnings = prepared.scene->warnings;
  prepared.warnings.insert(prepared.warnings.end(), prepared.inputs.warnings.begin(), prepared.inputs.warnings.end());
  return prepared;
}

}  // namespace facet
