#include "scene/load_scene.h"

#include "scene/default_scene.h"
#include "scene/gltf_loader.h"

namespace facet {

Scene loadScene(const std::string& path) {
  if (path.empty()) return makeDefaultScene();
  return loadGltf(path);
}

}  // namespace facet
