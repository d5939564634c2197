// The glTF loader on Debian's assimp-testmodels files.
#include <cstdint>
#include <functional>
#include <string>

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "scene/gltf_loader.h"
#include "scene/load_scene.h"

using namespace facet;

namespace {

const std::string kModels = FACET_ASSIMP_MODELS;

bool hasWarning(const Scene& scene, const std::string& text) {
  for (const std::string& w : scene.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("BoxTextured (.gltf, .glb, embedded): 12 triangles in the unit cube, one texture") {
  for (const char* file : {"/BoxTextured-glTF/BoxTextured.gltf", "/BoxTextured-glTF-Binary/BoxTextured.glb",
                           "/BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
    CAPTURE(file);
    const Scene scene = loadGltf(kModels + file);
    CHECK(scene.triangleCount() == 12);
    const Bounds b = scene.worldBounds();
    CHECK(b.min.x == doctest::Approx(-0.5f));
    CHECK(b.max.z == doctest::Approx(0.5f));
    REQUIRE(scene.materials.size() == 1);
    REQUIRE(scene.materials[0].baseColorTexture == 0);
    CHECK(scene.textures[0].image.width() == 211);
    CHECK(scene.meshes[0].texcoords.size() == scene.meshes[0].positions.size());
  }
}

TEST_CASE("2CylinderEngine: 121496 triangles over 115 instances, bounds from its node transforms") {
  const Scene scene = loadGltf(kModels + "/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
  CHECK(scene.instances.size() == 115);
  CHECK(scene.triangleCount() == 121496);
  const Bounds b = scene.worldBounds();
  CHECK(b.min.x == doctest::Approx(-371.7f).epsilon(1e-3));
  CHECK(b.max.x == doctest::Approx(371.7f).epsilon(1e-3));
  CHECK(b.min.y == doctest::Approx(-181.0f).epsilon(1e-3));
  CHECK(b.max.y == doctest::Approx(92.04f).epsilon(1e-3));
  CHECK(scene.warnings.empty());
}

TEST_CASE("glTF cameras are read with their node transforms") {
  const Scene scene = loadGltf(kModels + "/cameras/Cameras.gltf");
  REQUIRE(scene.cameras.size() == 2);
  CHECK(scene.cameras[0].projection == ProjectionKind::Perspective);
  CHECK(scene.cameras[1].projection == ProjectionKind::Parallel);
  CHECK(scene.cameras[0].eye.z > 0.0f);  // placed in front of the model, looking back at it
}

TEST_CASE("broken files: repaired with warnings or refused with one line naming the file") {
  SUBCASE("bad normals are recomputed") {
    const Scene scene = loadGltf(kModels + "/BoxBadNormals-glTF-Binary/BoxBadNormals.glb");
    CHECK(scene.triangleCount() == 12);
    CHECK(hasWarning(scene, "normals recomputed"));
  }
  SUBCASE("an out-of-range index drops its triangle") {
    const Scene scene = loadGltf(kModels + "/IndexOutOfRange/IndexOutOfRange.gltf");
    CHECK(scene.triangleCount() == 11);
    CHECK(hasWarning(scene, "ACCESSOR_INDEX_OOB"));
  }
  SUBCASE("infinite positions drop their triangles") {
    const Scene scene = loadGltf(kModels + "/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb");
    CHECK(hasWarning(scene, "ACCESSOR_INVALID_FLOAT"));
  }
  SUBCASE("a node loop is cut") {
    const Scene scene = loadGltf(kModels + "/RecursiveNodes/RecursiveNodes.gltf");
    CHECK(hasWarning(scene, "NODE_LOOP"));
  }
  SUBCASE("a missing buffer refuses the file") {
    const std::string path = kModels + "/MissingBin/BoxTextured.gltf";
    CHECK_THROWS_WITH_AS(loadGltf(path), doctest::Contains(path.c_str()), Error);
  }
  SUBCASE("a required extension we lack refuses the file") {
    CHECK_THROWS_WITH_AS(loadGltf(kModels + "/BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf"),
                         doctest::Contains("KHR_technique_webgl"), Error);
  }
  SUBCASE("Draco compression is required but not supported: named as such") {
    CHECK_THROWS_WITH_AS(loadGltf(kModels + "/draco/2CylinderEngine.gltf"), doctest::Contains("requires extension KHR_draco_mesh_compression"), Error);
  }
  SUBCASE("no such file") {
    CHECK_THROWS_WITH_AS(loadScene("/nonexistent/model.gltf"), "/nonexistent/model.gltf: no such file", Error);
  }
  SUBCASE("a directory is not a scene") {
    CHECK_THROWS_WITH_AS(loadScene(kModels), doctest::Contains("not a regular file"), Error);
  }
}

TEST_CASE("an empty path is the default scene and builtin: names a primitive") {
  CHECK(loadScene("").source == "default scene");
  CHECK(loadScene("builtin:default").source == "default scene");
  for (const char* name : {"builtin:sphere", "builtin:cube", "builtin:plane", "builtin:cylinder", "builtin:torus"}) {
    const Scene scene = loadScene(name);
    CHECK(scene.source == name);
    CHECK(scene.triangleCount() > 0);
    CHECK(scene.lights.empty());
    CHECK(scene.cameras.empty());
  }
  CHECK_THROWS_WITH_AS(loadScene("builtin:teapot"), doctest::Contains("no such built-in scene"), Error);
}

namespace {

// One triangle (positions in buffer bytes 0-35), two key times (36-43) and two translations (44-67).
constexpr const char* kTriangleAsset = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [1]},
                {"bufferView": 2, "componentType": 5126, "count": 2, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 8},
                  {"buffer": 0, "byteOffset": 44, "byteLength": 24}],
  "buffers": [{"byteLength": 68}]})";

std::string triangleBuffer() {
  const float values[17] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  return std::string(reinterpret_cast<const char*>(values), sizeof values);
}

// The asset with `change` applied, as a .gltf (buffer as a data URI) or a .glb (buffer in the BIN chunk).
std::string asset(const std::function<void(nlohmann::json&)>& change, bool binary) {
  nlohmann::json j = nlohmann::json::parse(kTriangleAsset);
  change(j);
  const std::string bin = triangleBuffer();
  if (!binary) {
    static constexpr char kBase64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string encoded;
    for (std::size_t i = 0; i < bin.size(); i += 3) {
      const std::size_t n = std::min<std::size_t>(3, bin.size() - i);
      unsigned v = 0;
      for (std::size_t k = 0; k < 3; ++k) v = v << 8 | (k < n ? static_cast<unsigned char>(bin[i + k]) : 0u);
      for (std::size_t k = 0; k < 4; ++k) encoded += k <= n ? kBase64[(v >> (18 - 6 * k)) & 63u] : '=';
    }
    j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + encoded;
    return j.dump();
  }
  std::string json = j.dump();
  while (json.size() % 4) json += ' ';
  std::string out = "glTF";
  const auto put32 = [&](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  put32(2);
  put32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  put32(static_cast<std::uint32_t>(json.size()));
  put32(0x4E4F534Au);
  out += json;
  put32(static_cast<std::uint32_t>(bin.size()));
  put32(0x004E4942u);
  out += bin;
  return out;
}

}  // namespace

TEST_CASE("valid files that tinygltf alone refuses are loaded: an animation channel without a target node") {
  for (const bool binary : {false, true}) {
    CAPTURE(binary);
    const std::string bytes = asset(
        [](nlohmann::json& j) {
          j["animations"] = nlohmann::json::parse(R"([{"channels": [{"sampler": 0, "target": {"path": "translation"}},
                                                                   {"sampler": 0, "target": {"node": 0, "path": "translation"}}],
                                                      "samplers": [{"input": 1, "output": 2}]}])");
        },
        binary);
    const Scene scene = loadGltfFromMemory(bytes, binary ? "animated.glb" : "animated.gltf", "");
    CHECK(scene.triangleCount() == 1);
    CHECK(scene.worldBounds().max.x == doctest::Approx(1.0f));  // drawn in its rest pose, from the BIN chunk of the rebuilt GLB too
    CHECK(hasWarning(scene, "animations[0].channels[0]: no target node"));
    CHECK_FALSE(hasWarning(scene, "channels[1]"));
  }
}

TEST_CASE("valid files that tinygltf alone refuses are loaded: a skin without inverseBindMatrices") {
  const std::string bytes = asset(
      [](nlohmann::json& j) {
        j["nodes"][0]["skin"] = 0;
        j["nodes"].push_back(nlohmann::json::object());
        j["skins"] = nlohmann::json::parse(R"([{"joints": [1]}])");
      },
      false);
  const Scene scene = loadGltfFromMemory(bytes, "skinned.gltf", "");
  CHECK(scene.triangleCount() == 1);
  CHECK(hasWarning(scene, "skinning is not supported"));
}

TEST_CASE("what glTF requires stays required: a spot light without its spot object (KHR_lights_punctual)") {
  CHECK_THROWS_AS(loadGltfFromMemory(asset(
                                         [](nlohmann::json& j) {
                                           j["extensions"] = nlohmann::json::parse(R"({"KHR_lights_punctual": {"lights": [{"type": "spot"}]}})");
                                           j["nodes"][0]["extensions"] = nlohmann::json::parse(R"({"KHR_lights_punctual": {"light": 0}})");
                                         },
                                         false),
                                     "spot.gltf", ""),
                  Error);
}
