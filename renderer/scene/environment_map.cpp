#include "scene/environment_map.h"

#include "common/error.h"
#include "image/png.h"

namespace facet {

EnvironmentMap loadEnvironmentMap(const std::string& path) {
  EnvironmentMap map;
  map.path = path;
  map.faces = readPng(path);
  const int w = map.faces.width(), h = map.faces.height();
  if (h < 1 || w != 6 * h)
    throw Error(path + ": " + std::to_string(w) + "x" + std::to_string(h) +
                " is not a cube map: six square faces side by side, 6N x N, in the order +x -x +y -y +z -z");
  return map;
}

void useEnvironment(Scene& scene, const EnvironmentSettings& settings) {
  if (settings.map == scene.environment.path) return;
  if (settings.map.empty()) {
    scene.environment = EnvironmentMap{};
  } else {
    try {
      scene.environment = loadEnvironmentMap(settings.map);
    } catch (const Error& e) {
      throw Error(std::string("environment.map: ") + e.what());
    }
  }
  scene.identity.renew();
}

}  // namespace facet
