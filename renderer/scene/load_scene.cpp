#include "scene/load_scene.h"

#include <glm/mat4x4.hpp>

#include "common/error.h"
#include "scene/cornell_box.h"
#include "scene/volume.h"
#include "scene/default_scene.h"
#include "scene/gltf_loader.h"
#include "scene/primitives.h"

namespace facet {
namespace {

constexpr std::string_view kBuiltin = "builtin:";

Scene primitiveScene(std::string_view name, Mesh mesh) {
  Scene scene;
  scene.source = std::string(kBuiltin) + std::string(name);
  Material m;
  m.name = "matte orange";
  m.baseColor = {0.9f, 0.45f, 0.15f, 1.0f};
  m.metallic = 0.0f;
  m.roughness = 0.4f;
  scene.materials.push_back(m);
  mesh.material = 0;
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back({0, glm::mat4(1.0f)});
  return scene;
}

// "+ground": a 6 m square ground under the primitive, a quarter metre below
// its lowest point, so that its shadow has something to fall on.
void addGround(Scene& scene) {
  const float floor = scene.worldBounds().min.y - 0.25f;
  const int material = scene.addMaterial("matte grey ground", {0.6f, 0.6f, 0.58f}, 0.0f, 0.9f);
  scene.addObject(makePlane(8), material, glm::mat4(3.0f, 0, 0, 0, 0, 1.0f, 0, 0, 0, 0, 3.0f, 0, 0, floor, 0, 1.0f));
}

Scene primitive(std::string_view name, const std::string& path) {
  if (name == "sphere") return primitiveScene(name, makeSphere(32));
  if (name == "cube") return primitiveScene(name, makeCube());
  if (name == "plane") return primitiveScene(name, makePlane(4));
  if (name == "cylinder") return primitiveScene(name, makeCylinder(48));
  if (name == "torus") return primitiveScene(name, makeTorus());
  std::string names;
  for (std::string_view n : builtinSceneNames()) names += (names.empty() ? "" : ", ") + std::string(n);
  throw Error(path + ": no such built-in scene (there are " + names + "; a primitive takes +ground)");
}

}  // namespace

std::vector<std::string_view> builtinSceneNames() { return {"default", "cornell", "fountain", "sphere", "cube", "plane", "cylinder", "torus"}; }

Scene loadScene(const std::string& path) {
  if (path.empty() || path == "builtin:default") return makeDefaultScene();
  if (path == "builtin:cornell") return makeCornellBox();
  if (path == "builtin:fountain") {
    // The default scene with a fountain on its ground, between the objects
    // (renderer/PIPELINE.md, "Particle systems"): the emitter's defaults.
    Scene scene = makeDefaultScene();
    scene.source = "builtin:fountain";
    Emitter fountain;
    fountain.position = {0.2f, 0.02f, -0.1f};
    fountain.rate = 600.0f;
    fountain.speed = 4.5f;
    fountain.spread = 10.0f;
    fountain.startSize = 0.06f;
    fountain.endSize = 0.12f;
    scene.emitters.push_back(fountain);
    return scene;
  }
  if (isVolumeName(path)) {  // a volume on its own, in an empty scene (pipeline/frame_spine.h reads it)
    Scene scene;
    scene.source = path;
    scene.files = {path};
    scene.volume.file = path;
    return scene;
  }
  if (path.rfind(kBuiltin, 0) != 0) return loadGltf(path);
  std::string_view name = std::string_view(path).substr(kBuiltin.size());
  constexpr std::string_view kGround = "+ground";
  const bool ground = name.size() > kGround.size() && name.substr(name.size() - kGround.size()) == kGround;
  if (ground) name.remove_suffix(kGround.size());
  Scene scene = primitive(name, path);
  if (ground) {
    addGround(scene);
    scene.source = path;
  }
  return scene;
}

}  // namespace facet
