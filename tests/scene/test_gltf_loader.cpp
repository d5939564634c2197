// The glTF loader on Debian's assimp-testmodels files.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/json_text.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/material_coefficients.h"
#include "ray/optics.h"
#include "scene/gltf_loader.h"
#include "scene/load_scene.h"
#include "scene/memory_budget.h"
#include "scene/vertex_tangents.h"

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

TEST_CASE("a scene lists the files it was read from: the glTF, then the buffers and images it names") {
  const Scene separate = loadGltf(kModels + "/BoxTextured-glTF/BoxTextured.gltf");
  REQUIRE(separate.files.size() == 3);
  CHECK(separate.files[0] == kModels + "/BoxTextured-glTF/BoxTextured.gltf");
  CHECK(separate.files[1].ends_with("/BoxTextured0.bin"));
  CHECK(separate.files[2].ends_with("/CesiumLogoFlat.png"));
  CHECK(loadGltf(kModels + "/BoxTextured-glTF-Binary/BoxTextured.glb").files.size() == 1);  // everything inside
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
    CHECK(hasWarning(scene, "meshes[0].primitives[0]: 1 triangle with an index past the 24 vertices (ACCESSOR_INDEX_OOB); dropped"));
  }
  SUBCASE("infinite positions drop their triangles") {
    const Scene scene = loadGltf(kModels + "/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb");
    CHECK(hasWarning(scene, "ACCESSOR_INVALID_FLOAT"));
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
    CHECK_THROWS_WITH_AS(loadGltf(kModels + "/draco/2CylinderEngine.gltf"), doctest::Contains("requires extension 'KHR_draco_mesh_compression', which facet does not support"), Error);
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

TEST_CASE("glTF animations: a translation channel moves its node's instance at settings.time, and what cannot be read is skipped, naming it") {
  const auto animated = [](const char* sampler) {
    return asset(
        [&](nlohmann::json& j) {
          j["animations"] = nlohmann::json::parse(std::string(R"([{"channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}],
                                                                     "samplers": [)") + sampler + "]}]");
        },
        false);
  };
  // Key times 0 and 1, translations (0, 0, 0) and (0, 1, 0): half way the triangle is half a unit up.
  const Scene scene = loadGltfFromMemory(animated(R"({"input": 1, "output": 2})"), "animated.gltf", "");
  REQUIRE(scene.animation.channels.size() == 1);
  RenderSettings s;
  s.time = 0.5f;
  CHECK(buildFrameInputs(scene, s).instances[0].worldFromModel[3].y == doctest::Approx(0.5f));
  s.time = 0.0f;
  CHECK(buildFrameInputs(scene, s).instances[0].worldFromModel == scene.instances[0].worldFromModel);
  // Times from a VEC3 accessor; an interpolation glTF does not have.
  const Scene wrong = loadGltfFromMemory(animated(R"({"input": 2, "output": 2})"), "animated.gltf", "");
  CHECK(wrong.animation.channels.empty());
  CHECK(hasWarning(wrong, "animations[0].channels[0]: accessors[2]: has 3 components per element, expected 1 (ACCESSOR_INVALID_TYPE); not animated"));
  const Scene smooth = loadGltfFromMemory(animated(R"({"input": 1, "output": 2, "interpolation": "SMOOTH"})"), "animated.gltf", "");
  CHECK(smooth.animation.channels.empty());
  CHECK(smooth.triangleCount() == 1);
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
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(asset(
                                              [](nlohmann::json& j) {
                                                j["extensions"] = nlohmann::json::parse(R"({"KHR_lights_punctual": {"lights": [{"type": "spot"}]}})");
                                                j["nodes"][0]["extensions"] = nlohmann::json::parse(R"({"KHR_lights_punctual": {"light": 0}})");
                                              },
                                              false),
                                          "spot.gltf", ""),
                       "spot.gltf: KHR_lights_punctual lights[0]: a spot light needs its spot object (innerConeAngle, outerConeAngle)", Error);
}

// ---------------------------------------------------------------------------
// Bad input: every file below is refused with one line naming the file, the
// object and the problem, or read with a warning naming what was dropped;
// none crashes, hangs, reads out of bounds or allocates more than the
// budgets of settings/render_settings.h. Most are built here; the few in
// tests/data/gltf are the issue's own small files.

namespace {

const std::string kData = FACET_TEST_DATA "/gltf";

// doctest::Contains of a built string (it copies the text).
doctest::Contains has(const std::string& text) { return doctest::Contains(text.c_str()); }

std::string u32(std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); }

// A GLB of `json` (padded with spaces) and `bin`, as a writer following glTF 2.0, 4.4 makes it.
std::string glb(std::string json, const std::string& bin) {
  while (json.size() % 4) json += ' ';
  std::string out = "glTF" + u32(2) + u32(static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size()))) +
                    u32(static_cast<std::uint32_t>(json.size())) + "JSON" + json;
  if (!bin.empty()) out += u32(static_cast<std::uint32_t>(bin.size())) + std::string("BIN\0", 4) + bin;
  return out;
}

// The PNG signature and an IHDR chunk of w×h RGBA pixels, and nothing after:
// enough for an image header, not for pixels.
std::string pngHeader(std::uint32_t w, std::uint32_t h) {
  const auto be = [](std::uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
  return std::string("\x89PNG\r\n\x1a\n", 8) + be(13) + "IHDR" + be(w) + be(h) + std::string("\x08\x06\x00\x00\x00", 5) + be(0);
}

std::string dataUri(const std::string& bytes) {
  static constexpr char kBase64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string encoded;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    unsigned v = 0;
    for (std::size_t k = 0; k < 3; ++k) v = v << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) encoded += k <= n ? kBase64[(v >> (18 - 6 * k)) & 63u] : '=';
  }
  return "data:application/octet-stream;base64," + encoded;
}

std::string floats(std::initializer_list<float> values) {
  std::string out;
  for (float v : values) out.append(reinterpret_cast<const char*>(&v), sizeof v);
  return out;
}

Scene loadJson(const nlohmann::json& document, const std::string& name = "bad.gltf") { return loadGltfFromMemory(document.dump(), name, ""); }

nlohmann::json triangle() { return nlohmann::json::parse(asset([](nlohmann::json&) {}, false)); }

// The triangle with a KHR_lights_punctual light on a second root node.
nlohmann::json withLight(const nlohmann::json& light) {
  nlohmann::json j = triangle();
  j["extensionsUsed"] = {"KHR_lights_punctual"};
  j["extensions"]["KHR_lights_punctual"]["lights"] = nlohmann::json::array({light});
  j["nodes"].push_back({{"translation", {0, 2, 1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  j["scenes"][0]["nodes"] = {0, 1};
  return j;
}

}  // namespace

TEST_CASE("glTF bad input: an image whose bufferView lies past its buffer is refused before anything reads it") {
  // The issue's file: an image at byteOffset 2^40 (it crashed `facet info`).
  CHECK_THROWS_WITH_AS(loadGltf(kData + "/image_view_at_2p40.glb"),
                       doctest::Contains("image_view_at_2p40.glb: images[0]: bufferViews[1]: byteOffset 1099511627776 + byteLength 75 runs past "
                                         "the end of buffers[0], which has 111 bytes (BUFFER_VIEW_TOO_LONG)"),
                       Error);
  // Just past the end (it read invalid memory and drew), and a length that overflows offset + length.
  for (const auto& view : {std::pair<std::uint64_t, std::uint64_t>{40, 75}, {1, 0xffffffffffffffffull}}) {
    const std::uint64_t offset = view.first, length = view.second;  // named, not bound: CAPTURE's lambda takes them
    CAPTURE(offset);
    nlohmann::json j = triangle();
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}});
    j["images"] = {{{"bufferView", 3}, {"mimeType", "image/png"}}};
    CHECK_THROWS_WITH_AS(loadJson(j), has("bad.gltf: images[0]: bufferViews[3]: byteOffset " + std::to_string(offset)), Error);
  }
  nlohmann::json j = triangle();
  j["images"] = {{{"bufferView", 9}, {"mimeType", "image/png"}}};
  CHECK_THROWS_WITH_AS(loadJson(j), doctest::Contains("images[0]: bufferView '9' does not exist"), Error);
}

TEST_CASE("glTF bad input: sparse accessors are read, their indices and values held to their bufferViews") {
  // Vertex 2 of the triangle replaced by (0, 5, 0): indices (one UNSIGNED_INT) and values (one VEC3) in a second buffer.
  const auto sparseTriangle = [](std::uint32_t index, std::size_t valuesLength) {
    nlohmann::json j = triangle();
    const std::string bytes = u32(index) + floats({0, 5, 0});
    j["buffers"].push_back({{"byteLength", bytes.size()}, {"uri", dataUri(bytes)}});
    j["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 4}});
    j["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 4}, {"byteLength", valuesLength}});
    j["accessors"][0]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", 3}, {"componentType", 5125}}}, {"values", {{"bufferView", 4}}}};
    return j;
  };
  const Scene good = loadJson(sparseTriangle(2, 12));
  REQUIRE(good.meshes.size() == 1);
  CHECK(good.meshes[0].positions[2] == glm::vec3(0, 5, 0));
  CHECK(good.meshes[0].positions[1] == glm::vec3(1, 0, 0));  // the base where no index replaces it

  const Scene shortValues = loadJson(sparseTriangle(2, 8));  // 8 bytes hold no VEC3
  CHECK(shortValues.meshes.empty());
  CHECK(hasWarning(shortValues, "accessors[0].sparse.values: needs 12 bytes but its bufferView has 8 (ACCESSOR_TOO_LONG); skipped"));
  const Scene pastCount = loadJson(sparseTriangle(3, 12));  // the accessor has elements 0..2
  CHECK(hasWarning(pastCount, "accessors[0].sparse.indices: element 0 is 3, past the accessor's 3 elements (ACCESSOR_SPARSE_INDEX_OOB)"));
  nlohmann::json pastBuffer = sparseTriangle(2, 12);
  pastBuffer["bufferViews"][4]["byteOffset"] = 8;  // 8 + 12 > the buffer's 16 bytes
  CHECK(hasWarning(loadJson(pastBuffer), "bufferViews[4]: byteOffset 8 + byteLength 12 runs past its buffer of 16 bytes (BUFFER_VIEW_TOO_LONG)"));
}

TEST_CASE("glTF accessors without a bufferView read as zeros, then their sparse values, as indices and as attributes, priced by count") {
  // Indices: three UNSIGNED_INT zeros without a bufferView, elements 1 and 2 replaced by 1 and 2 (sparse).
  const auto withIndices = [](bool sparse, bool binary) {
    nlohmann::json j = triangle();
    const std::string bytes = u32(1) + u32(2) + u32(1) + u32(2);
    j["buffers"].push_back({{"byteLength", bytes.size()}, {"uri", dataUri(bytes)}});
    j["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 8}});
    j["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 8}, {"byteLength", 8}});
    j["accessors"].push_back({{"componentType", 5125}, {"count", 3}, {"type", "SCALAR"}});
    if (sparse)
      j["accessors"][3]["sparse"] = {{"count", 2}, {"indices", {{"bufferView", 3}, {"componentType", 5125}}}, {"values", {{"bufferView", 4}}}};
    j["meshes"][0]["primitives"][0]["indices"] = 3;
    if (!binary) return loadJson(j, "zeros.gltf");
    const std::string bin = triangleBuffer();
    j["buffers"][0].erase("uri");
    return loadGltfFromMemory(glb(j.dump(), bin), "zeros.glb", "");
  };
  for (const bool binary : {false, true}) {
    CAPTURE(binary);
    const Scene sparse = withIndices(true, binary);
    REQUIRE(sparse.meshes.size() == 1);
    CHECK(sparse.meshes[0].indices == std::vector<std::uint32_t>{0, 1, 2});
    CHECK(sparse.triangleCount() == 1);
    const Scene zeros = withIndices(false, binary);
    REQUIRE(zeros.meshes.size() == 1);
    CHECK(zeros.meshes[0].indices == std::vector<std::uint32_t>{0, 0, 0});
  }
  // Positions: zeros but vertex 1, from a sparse accessor without a bufferView.
  nlohmann::json j = triangle();
  const std::string bytes = u32(1) + floats({2, 0, 0});
  j["buffers"].push_back({{"byteLength", bytes.size()}, {"uri", dataUri(bytes)}});
  j["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 4}});
  j["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 4}, {"byteLength", 12}});
  j["accessors"][0] = {{"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                       {"sparse", {{"count", 1}, {"indices", {{"bufferView", 3}, {"componentType", 5125}}}, {"values", {{"bufferView", 4}}}}}};
  const Scene positions = loadJson(j);
  REQUIRE(positions.meshes.size() == 1);
  CHECK(positions.meshes[0].positions == std::vector<glm::vec3>{glm::vec3(0), glm::vec3(2, 0, 0), glm::vec3(0)});
  // The zeros are priced as any accessor's elements, before they are made.
  nlohmann::json huge = triangle();
  huge["accessors"].push_back({{"componentType", 5125}, {"count", 1 << 28}, {"type", "SCALAR"}});
  huge["meshes"][0]["primitives"][0]["indices"] = 3;
  CHECK_THROWS_WITH_AS(loadJson(huge, "huge.gltf"), doctest::Contains("huge.gltf: meshes[0].primitives[0]: 3 vertices (accessors[0]) and 268435456 indices need"),
                       Error);
}

TEST_CASE("glTF buffers without a uri: unused ones load (a .gltf's, a GLB's beyond buffer 0), a used one is refused naming who reads it") {
  // A .gltf: the triangle's buffer plus buffers[1] with no uri (and so no data), which no bufferView names.
  nlohmann::json j = triangle();
  j["buffers"].push_back({{"byteLength", 1000}});
  const Scene text = loadJson(j, "unused.gltf");
  CHECK(text.triangleCount() == 1);
  CHECK(text.warnings.empty());
  // A GLB: buffers[0] is the BIN chunk, buffers[1] a placeholder longer than the chunk.
  nlohmann::json b = j;
  b["buffers"][0].erase("uri");
  const Scene binary = loadGltfFromMemory(glb(b.dump(), triangleBuffer()), "unused.glb", "");
  CHECK(binary.triangleCount() == 1);
  CHECK(binary.worldBounds().max.x == doctest::Approx(1.0f));
  CHECK(binary.warnings.empty());
  // Used: a bufferView in it, read by an accessor (the indices), or by nothing.
  j["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 12}});
  j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5125}, {"count", 3}, {"type", "SCALAR"}});
  j["meshes"][0]["primitives"][0]["indices"] = 3;
  CHECK_THROWS_WITH_AS(loadJson(j, "used.gltf"),
                       "used.gltf: buffers[1]: has no uri, so it holds no data, but bufferViews[3] lies in it and accessors[3] reads that bufferView", Error);
  b["bufferViews"] = j["bufferViews"];
  b["accessors"] = j["accessors"];
  b["accessors"].erase(3);
  b["meshes"][0]["primitives"][0].erase("indices");
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(glb(b.dump(), triangleBuffer()), "used.glb", ""),
                       "used.glb: buffers[1]: has no uri, so it holds no data, but bufferViews[3] lies in it", Error);
}

TEST_CASE("glTF data: URIs for buffers inside a GLB load, beside the BIN chunk or without one") {
  // buffers[0] the BIN chunk, buffers[1] a data: URI holding the second triangle's positions.
  nlohmann::json j = triangle();
  j["buffers"][0].erase("uri");
  j["buffers"].push_back({{"byteLength", 36}, {"uri", dataUri(floats({0, 0, 1, 1, 0, 1, 0, 1, 1}))}});
  j["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 36}});
  j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}, {"min", {0, 0, 1}}, {"max", {1, 1, 1}}});
  j["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 3}}}});
  const Scene both = loadGltfFromMemory(glb(j.dump(), triangleBuffer()), "both.glb", "");
  CHECK(both.triangleCount() == 2);
  CHECK(both.worldBounds().max.z == doctest::Approx(1.0f));
  CHECK(both.warnings.empty());
  // Only data: URIs, no BIN chunk.
  nlohmann::json only = triangle();
  const Scene uris = loadGltfFromMemory(glb(only.dump(), ""), "uris.glb", "");
  CHECK(uris.triangleCount() == 1);
  CHECK(uris.warnings.empty());
}

namespace {

// A quad over (0, 0)-(1, 1) facing +z: its POSITION, NORMAL and TEXCOORD_0 each `count` bytes a vertex in
// their own bufferView (that stride), of componentType `type` and `normalized` as given; indices 0 1 2 0 2 3.
struct QuadAttribute {
  int type;
  bool normalized;
  std::size_t stride;
  std::string bytes;  // four elements, each padded to the stride
};

nlohmann::json quad(const QuadAttribute& position, const QuadAttribute& normal, const QuadAttribute& texcoord, const nlohmann::json& node) {
  const std::string indices = std::string{0, 1, 2, 0, 2, 3, 0, 0};
  const std::string bin = position.bytes + normal.bytes + texcoord.bytes + indices;
  nlohmann::json j = nlohmann::json::parse(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3}]}]})");
  j["nodes"] = nlohmann::json::array({node});
  j["nodes"][0]["mesh"] = 0;
  j["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}, {"uri", dataUri(bin)}}});
  std::size_t offset = 0;
  int index = 0;
  for (const QuadAttribute* a : {&position, &normal, &texcoord}) {
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", a->bytes.size()}, {"byteStride", a->stride}});
    j["accessors"].push_back({{"bufferView", index}, {"componentType", a->type}, {"normalized", a->normalized}, {"count", 4},
                              {"type", index == 2 ? "VEC2" : "VEC3"}});
    offset += a->bytes.size();
    ++index;
  }
  j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", 6}});
  j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5121}, {"count", 6}, {"type", "SCALAR"}});
  return j;
}

// Four elements of `components` values of type T each, padded with zeros to `stride` bytes.
template <class T>
std::string elements(std::initializer_list<std::initializer_list<T>> values, std::size_t stride) {
  std::string out;
  for (const auto& element : values) {
    std::string e;
    for (T v : element) e.append(reinterpret_cast<const char*>(&v), sizeof v);
    e.resize(stride, '\0');
    out += e;
  }
  return out;
}

// The mesh's vertex positions placed by its instance's node transform.
std::vector<glm::vec3> placedPositions(const Scene& scene) {
  std::vector<glm::vec3> out;
  for (const glm::vec3& p : scene.meshes.at(0).positions) out.push_back(glm::vec3(scene.instances.at(0).worldFromModel * glm::vec4(p, 1.0f)));
  return out;
}

}  // namespace

TEST_CASE("glTF KHR_mesh_quantization: integer positions, normals and texture coordinates read as the float quad, placed exactly") {
  const QuadAttribute floatPositions{5126, false, 12, floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0})};
  const QuadAttribute floatNormals{5126, false, 12, floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1})};
  const QuadAttribute floatTexcoords{5126, false, 8, floats({0, 0, 1, 0, 1, 1, 0, 1})};
  nlohmann::json reference = quad(floatPositions, floatNormals, floatTexcoords, nlohmann::json::object());
  reference.erase("extensionsUsed");
  reference.erase("extensionsRequired");
  const Scene expected = loadJson(reference, "float.gltf");
  REQUIRE(expected.triangleCount() == 2);
  const std::vector<glm::vec3> expectedPositions = placedPositions(expected);

  struct Variant {
    const char* name;
    QuadAttribute position, normal, texcoord;
    nlohmann::json node;
  };
  const Variant variants[] = {
      // Unsigned shorts as their values (0 and 2), scaled by the node by 1/2; normalized bytes; unsigned bytes as their values.
      {"ushort", {5123, false, 8, elements<std::uint16_t>({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, 8)},
       {5120, true, 4, elements<std::int8_t>({{0, 0, 127}, {0, 0, 127}, {0, 0, 127}, {0, 0, 127}}, 4)},
       {5121, false, 4, elements<std::uint8_t>({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 4)}, {{"scale", {0.5, 0.5, 0.5}}}},
      // Normalized bytes (127 is 1); normalized shorts; normalized unsigned shorts.
      {"byte", {5120, true, 4, elements<std::int8_t>({{0, 0, 0}, {127, 0, 0}, {127, 127, 0}, {0, 127, 0}}, 4)},
       {5122, true, 8, elements<std::int16_t>({{0, 0, 32767}, {0, 0, 32767}, {0, 0, 32767}, {0, 0, 32767}}, 8)},
       {5123, true, 4, elements<std::uint16_t>({{0, 0}, {65535, 0}, {65535, 65535}, {0, 65535}}, 4)}, nlohmann::json::object()},
      // Normalized bytes mirrored in x by the node: -128 is clamped to -1; signed shorts as their values.
      {"mirrored", {5120, true, 4, elements<std::int8_t>({{0, 0, 0}, {-128, 0, 0}, {-127, 127, 0}, {0, 127, 0}}, 4)},
       {5120, true, 4, elements<std::int8_t>({{0, 0, 127}, {0, 0, 127}, {0, 0, 127}, {0, 0, 127}}, 4)},
       {5122, false, 4, elements<std::int16_t>({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 4)}, {{"scale", {-1, 1, 1}}}},
  };
  for (const Variant& v : variants) {
    CAPTURE(v.name);
    const Scene scene = loadJson(quad(v.position, v.normal, v.texcoord, v.node), "quantized.gltf");
    CHECK(scene.warnings.empty());
    REQUIRE(scene.triangleCount() == 2);
    CHECK(placedPositions(scene) == expectedPositions);
    CHECK(scene.meshes[0].normals == expected.meshes[0].normals);
    CHECK(scene.meshes[0].texcoords == expected.meshes[0].texcoords);
  }
  // What the extension does not allow stays refused by name: unsigned or not-normalized normals.
  const Scene odd = loadJson(quad(floatPositions, {5121, true, 4, elements<std::uint8_t>({{0, 0, 255}, {0, 0, 255}, {0, 0, 255}, {0, 0, 255}}, 4)},
                                  floatTexcoords, nlohmann::json::object()),
                             "odd.gltf");
  CHECK(hasWarning(odd, "meshes[0].primitives[0]: NORMAL accessors[1]: normals must be FLOAT or normalized BYTE/SHORT"));
}

TEST_CASE("glTF bad input: a node hierarchy that is not a set of trees is refused at once, naming the node") {
  // The issue's file: 41 nodes, each the child of the two before it (2^40 paths; it never finished).
  CHECK_THROWS_WITH_AS(loadGltf(kData + "/node_dag_41.gltf"),
                       doctest::Contains("node_dag_41.gltf: nodes[2]: is a child of both nodes[0] and nodes[1], but a glTF node has at most "
                                         "one parent (NODE_PARENT_OVERRIDE)"),
                       Error);
  const auto nodes = [](const char* list, const char* roots) {
    nlohmann::json j = triangle();
    j["nodes"] = nlohmann::json::parse(list);
    j["scenes"][0]["nodes"] = nlohmann::json::parse(roots);
    return j;
  };
  CHECK_THROWS_WITH_AS(loadJson(nodes(R"([{"mesh": 0, "children": [1]}, {"children": [2]}, {"children": [1]}])", "[0]")),
                       doctest::Contains("nodes[1]: is a child of both nodes[0] and nodes[2]"), Error);
  CHECK_THROWS_WITH_AS(loadJson(nodes(R"([{"mesh": 0}, {"children": [2], "name": "a"}, {"children": [1]}])", "[0]")),
                       doctest::Contains("bad.gltf: nodes[1] 'a': is its own ancestor (NODE_LOOP"), Error);
  CHECK_THROWS_WITH_AS(loadJson(nodes(R"([{"mesh": 0, "children": [0]}])", "[0]")), doctest::Contains("nodes[0]: is its own child (NODE_LOOP"),
                       Error);
  CHECK_THROWS_WITH_AS(loadJson(nodes(R"([{"children": [1, 1]}, {"mesh": 0}])", "[0]")),
                       doctest::Contains("nodes[1]: is listed twice among the children of nodes[0]"), Error);
  CHECK_THROWS_WITH_AS(loadJson(nodes(R"([{"children": [1]}, {"mesh": 0}])", "[0, 1]")),
                       doctest::Contains("scenes[0]: nodes[1] is a root of the scene but a child of nodes[0] (SCENE_NON_ROOT_NODE)"), Error);
  CHECK_THROWS_WITH_AS(loadJson(nodes(R"([{"mesh": 0}])", "[0, 0]")), doctest::Contains("scenes[0]: lists nodes[0] twice"), Error);
  CHECK_THROWS_WITH_AS(loadGltf(kModels + "/RecursiveNodes/RecursiveNodes.gltf"), doctest::Contains("nodes[0]: is its own ancestor (NODE_LOOP"),
                       Error);
  // A tree that shares a mesh between nodes is fine: one instance per node.
  CHECK(loadJson(nodes(R"([{"mesh": 0, "children": [1, 2]}, {"mesh": 0}, {"mesh": 0, "children": [3]}, {"mesh": 0}])", "[0]")).instances.size() == 4);
}

TEST_CASE("glTF bad input: memory is priced from counts and image headers before it is allocated") {
  // The issue's file: 900 bytes, one accessor of 2^26 zero vertices without a bufferView (1.6 GB for info).
  CHECK_THROWS_WITH_AS(loadGltf(kData + "/zeros_accessor_2p26.gltf"),
                       doctest::Contains("zeros_accessor_2p26.gltf: meshes[0].primitives[0]: 67108864 vertices (accessors[0]) and 67108864 "
                                         "indices need 1.88 GB, more than the scene budget of 1 GiB"),
                       Error);
  // 8192² images take 358 MB with their mipmaps: three fit, the fourth is refused from its header;
  // nothing is decoded (only headers exist here).
  nlohmann::json j = triangle();
  for (int i = 0; i < 4; ++i) {
    j["images"].push_back({{"uri", dataUri(pngHeader(8192, 8192))}});
    j["textures"].push_back({{"source", i}});
  }
  CHECK_THROWS_WITH_AS(loadJson(j), doctest::Contains("bad.gltf: images[3]: 8192x8192 RGBA pixels and their mipmaps need 358 MB, which with the 1.07 GB "
                                                      "counted before is more than the scene budget of 1 GiB"),
                       Error);
  // Textures sharing one image: each copy beyond the first is priced too.
  nlohmann::json shared = triangle();
  shared["images"] = {{{"uri", dataUri(pngHeader(16384, 12000))}}};
  shared["textures"] = {{{"source", 0}}, {{"source", 0}}};
  CHECK_THROWS_WITH_AS(loadJson(shared), doctest::Contains("textures[0]: another copy of the 16384x12000 pixels of images[0]"), Error);
  // Nodes that place one big mesh many times: priced as the frame will hold them, refused naming the node.
  nlohmann::json instances = triangle();
  instances["accessors"][0] = {{"componentType", 5126}, {"count", 3 * 262144}, {"type", "VEC3"}};
  instances["nodes"] = nlohmann::json::array();
  for (int n = 0; n < 100; ++n) instances["nodes"].push_back({{"mesh", 0}});
  instances["scenes"][0]["nodes"] = nlohmann::json::array();
  for (int n = 0; n < 100; ++n) instances["scenes"][0]["nodes"].push_back(n);
  CHECK_THROWS_WITH_AS(loadJson(instances), doctest::Contains("bad.gltf: nodes[7]: the 786432 vertices and 262144 triangles of its instance of meshes[0] "
                                                              "need 132 MiB, which with the 924 MiB counted before is more than the frame budget of 1 GiB"),
                       Error);
  instances["scenes"][0]["nodes"] = {0, 1, 2, 3, 4, 5, 6};
  CHECK(loadJson(instances).instances.size() == 7);
}

TEST_CASE("glTF bad input: the budgets' messages name what needs how much") {
  CHECK(byteCount(std::uint64_t{1} << 30) == "1 GiB");
  CHECK(byteCount(std::uint64_t{512} << 20) == "512 MiB");
  CHECK(byteCount(805306368 + 1) == "805 MB");
  CHECK(byteCount(1879048192 + 1) == "1.88 GB");
  CHECK(byteCount(999) == "999 bytes");
  MemoryBudget budget(1000, "test budget");
  budget.charge(600, "a: six hundred bytes");
  CHECK(budget.used() == 600);
  CHECK_THROWS_WITH_AS(budget.charge(500, "b: five hundred bytes"),
                       "b: five hundred bytes need 500 bytes, which with the 600 bytes counted before is more than the test budget of 1.00 kB", Error);
  CHECK_THROWS_WITH_AS(budget.charge(std::uint64_t{1} << 63, "c: too many"), doctest::Contains("c: too many need 9.22 EB, more than the test budget"), Error);
  CHECK(budget.used() == 600);
  budget.charge(400, "d: the rest");
  CHECK(budget.used() == 1000);
}

TEST_CASE("glTF bad input: a file that is not glTF is named for what it is, its bytes never echoed raw") {
  CHECK_THROWS_WITH_AS(loadGltf(kData + "/utf16.gltf"), doctest::Contains("utf16.gltf: not a glTF file (.gltf must be UTF-8 JSON, and this is UTF-16LE text)"),
                       Error);
  const std::string json = triangle().dump();
  std::string utf16be, utf32;
  for (char c : json) utf16be += std::string{'\0', c}, utf32 += std::string{c, '\0', '\0', '\0'};
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(utf16be, "be.gltf", ""), doctest::Contains("this is UTF-16BE text"), Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(utf32, "le.gltf", ""), doctest::Contains("this is UTF-32LE text"), Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(pngHeader(4, 4), "image.gltf", ""), "image.gltf: is a PNG image, not a glTF file", Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(pngHeader(4, 4), "image.glb", ""), "image.glb: is a PNG image, not a glTF file", Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory("\xff\xd8\xff\xe0 JFIF", "photo.gltf", ""), "photo.gltf: is a JPEG image, not a glTF file", Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory("", "empty.gltf", ""), "empty.gltf: not a glTF file (.gltf is empty)", Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory("solid cube\x01\x02", "cube.gltf", ""),
                       "cube.gltf: not a glTF file (.gltf must be UTF-8 JSON holding an object, and it starts with 'solid cube\\x01\\x02')", Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory("[1, 2]", "array.gltf", ""), doctest::Contains("array.gltf: not a glTF file (.gltf must be UTF-8 JSON holding an object"),
                       Error);
  // A syntax error: nlohmann's words, the text around it quoted with its control bytes escaped.
  CHECK_THROWS_WITH_AS(loadGltfFromMemory("{\"asset\": \x01}", "syntax.gltf", ""),
                       doctest::Contains("syntax.gltf: not valid JSON at line 1, column 11: syntax error while parsing value - invalid literal"),
                       Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory("{\"asset\": \x01}", "syntax.gltf", ""), doctest::Contains("near '{\"asset\": \\x01}'"), Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory("{\"a\": 1e999}", "overflow.gltf", ""), "overflow.gltf: not valid JSON: number overflow parsing '1e999'", Error);
  // glTF JSON is UTF-8 text, which holds no NUL: what follows one is not silently dropped.
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(json + std::string("\0{\"more\": 1}", 12), "nul.gltf", ""),
                       has("nul.gltf: a NUL byte at byte " + std::to_string(json.size()) + " of the .gltf, where JSON text cannot hold one (glTF JSON is UTF-8 text)"),
                       Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(glb(json + std::string("\0\0\0\0", 4), ""), "nul.glb", ""),
                       has("nul.glb: a NUL byte at byte " + std::to_string(json.size()) + " of the GLB's JSON chunk"), Error);
}

TEST_CASE("glTF bad input: a malformed GLB is reported as exactly what is wrong with its chunks") {
  nlohmann::json document = triangle();
  document["buffers"][0].erase("uri");
  const std::string bin = triangleBuffer();
  const std::string good = glb(document.dump(), bin);
  CHECK(loadGltfFromMemory(good, "good.glb", "").triangleCount() == 1);

  std::string json = document.dump();
  while (json.size() % 4 != 1) json += ' ';  // a JSON chunk length that is not a multiple of 4 (it read as a 1.2 GB BIN chunk)
  const std::string unaligned = "glTF" + u32(2) + u32(static_cast<std::uint32_t>(20 + json.size() + 8 + bin.size())) +
                                u32(static_cast<std::uint32_t>(json.size())) + "JSON" + json + u32(static_cast<std::uint32_t>(bin.size())) +
                                std::string("BIN\0", 4) + bin;
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(unaligned, "padding.glb", ""),
                       has("padding.glb: GLB JSON chunk at byte 12 is " + std::to_string(json.size()) +
                           " bytes long, not a multiple of 4: chunks are padded to 4-byte boundaries (GLB_CHUNK_LENGTH_UNALIGNED)"),
                       Error);
  std::string tooBig = good;
  const std::size_t binHeader = good.size() - bin.size() - 8;
  tooBig.replace(binHeader, 4, u32(1200000000));
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(tooBig, "big.glb", ""),
                       has("big.glb: GLB BIN chunk at byte " + std::to_string(binHeader) + " declares 1200000000 bytes, but the file ends " +
                           std::to_string(bin.size()) + " bytes after its header (GLB_CHUNK_TOO_BIG)"),
                       Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(good + "xy", "long.glb", ""),
                       has("long.glb: GLB header declares " + std::to_string(good.size()) + " bytes, but the file has " +
                           std::to_string(good.size() + 2) + " (GLB_LENGTH_MISMATCH)"),
                       Error);
  std::string tail = good + "1234";
  tail.replace(8, 4, u32(static_cast<std::uint32_t>(tail.size())));
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(tail, "tail.glb", ""), doctest::Contains("too few for a chunk header of 8 (GLB_UNEXPECTED_END_OF_CHUNK_HEADER)"),
                       Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(good.substr(0, 10), "short.glb", ""), doctest::Contains("(GLB_UNEXPECTED_END_OF_HEADER)"), Error);
  CHECK_THROWS_WITH_AS(loadGltfFromMemory("{}", "json.glb", ""), "json.glb: not a GLB file: it starts with '{}', not 'glTF' (GLB_INVALID_MAGIC)", Error);
  // A chunk of an unknown type is skipped, as glTF requires; the file loads.
  std::string extra = good + u32(4) + "XTRA" + "abcd";
  extra.replace(8, 4, u32(static_cast<std::uint32_t>(extra.size())));
  CHECK(loadGltfFromMemory(extra, "extra.glb", "").triangleCount() == 1);
  std::string twoBins = good + u32(4) + std::string("BIN\0", 4) + "abcd";
  twoBins.replace(8, 4, u32(static_cast<std::uint32_t>(twoBins.size())));
  CHECK_THROWS_WITH_AS(loadGltfFromMemory(twoBins, "two.glb", ""), has("has a second BIN chunk at byte " + std::to_string(good.size())), Error);
}

TEST_CASE("glTF bad input: a buffer file that exists but is not read says why, not \"File not found\"") {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("facet-gltf-uris-" + std::to_string(::getpid()));
  fs::create_directories(folder / "sub");
  const auto scene = [&](const std::string& uri) {
    nlohmann::json j = triangle();
    j["buffers"][0]["uri"] = uri;
    const std::string path = (folder / "scene.gltf").string();
    std::ofstream(path) << j.dump();
    return path;
  };
  std::ofstream(folder / "triangle.bin", std::ios::binary) << triangleBuffer();
  CHECK(loadGltf(scene("triangle.bin")).triangleCount() == 1);
  CHECK(loadGltf(scene("tri%61ngle.bin")).triangleCount() == 1);  // percent-decoded as tinygltf decodes it
  CHECK_THROWS_WITH_AS(loadGltf(scene("/dev/zero")), doctest::Contains("scene.gltf: buffers[0]: uri '/dev/zero': not a regular file"), Error);
  CHECK_THROWS_WITH_AS(loadGltf(scene("sub")), doctest::Contains("buffers[0]: uri 'sub': not a regular file"), Error);
  CHECK_THROWS_WITH_AS(loadGltf(scene("missing.bin")), doctest::Contains("buffers[0]: uri 'missing.bin': no such file"), Error);
  CHECK_THROWS_WITH_AS(loadGltf(scene("../" + folder.filename().string() + "/../" + folder.filename().string() + "-elsewhere.bin")),
                       doctest::Contains("no such file"), Error);
  std::ofstream(folder.string() + "-outside.bin", std::ios::binary) << triangleBuffer();
  CHECK_THROWS_WITH_AS(loadGltf(scene("../" + folder.filename().string() + "-outside.bin")),
                       doctest::Contains("outside the scene's folder, where facet reads no files"), Error);
  fs::remove(folder.string() + "-outside.bin");
  fs::remove_all(folder);
}

TEST_CASE("glTF bad input: a node's KHR_lights_punctual light that does not exist is ignored with a warning, whatever number it is") {
  // 6.7e74 (a fuzzer's) was converted to int by tinygltf's GetNumberAsInt, which is undefined.
  for (const nlohmann::json& reference : {nlohmann::json(6.666666666666667e74), nlohmann::json(1), nlohmann::json(-1), nlohmann::json(0.5),
                                          nlohmann::json("zero")}) {
    CAPTURE(reference.dump());
    nlohmann::json j = withLight({{"type", "point"}});
    j["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = reference;
    const Scene scene = loadJson(j);
    CHECK(scene.lights.empty());
    CHECK(hasWarning(scene, "nodes[1]: KHR_lights_punctual light " + (reference.is_number() ? exactNumber(reference.get<double>()) : "(not a number)") +
                                " does not exist (UNRESOLVED_REFERENCE); ignored"));
  }
  CHECK(loadJson(withLight({{"type", "point"}})).lights.size() == 1);
}

TEST_CASE("glTF bad input: KHR_lights_punctual lights must have a known type and a valid spot cone, named when not") {
  CHECK_THROWS_WITH_AS(loadGltf(kData + "/laser_light.gltf"),
                       doctest::Contains("laser_light.gltf: KHR_lights_punctual lights[0] 'pew': type 'laser' is not one of directional, point, spot"),
                       Error);
  CHECK_THROWS_WITH_AS(loadJson(withLight({{"type", 7}})), doctest::Contains("lights[0]: type '7' is not one of"), Error);
  CHECK_THROWS_WITH_AS(loadJson(withLight({{"intensity", 1}})), doctest::Contains("lights[0]: has no type"), Error);
  // 0 ≤ innerConeAngle < outerConeAngle ≤ π/2 (defaults 0 and π/4).
  for (const auto& cone : std::vector<std::pair<double, double>>{{0, -1.0}, {0, 1.6}, {0.5, 0.5}, {0.6, 0.5}, {-0.1, 0.5}, {0, 0}}) {
    const double inner = cone.first, outer = cone.second;  // named, not bound: CAPTURE's lambda takes them
    CAPTURE(inner);
    CAPTURE(outer);
    CHECK_THROWS_WITH_AS(loadJson(withLight({{"type", "spot"}, {"name", "desk"}, {"spot", {{"innerConeAngle", inner}, {"outerConeAngle", outer}}}})),
                         doctest::Contains("bad.gltf: KHR_lights_punctual lights[0] 'desk': spot.innerConeAngle "), Error);
  }
  CHECK_THROWS_WITH_AS(loadJson(withLight({{"type", "spot"}, {"spot", {{"outerConeAngle", -1.0}}}})),
                       "bad.gltf: KHR_lights_punctual lights[0]: spot.innerConeAngle 0 rad (0 deg) and outerConeAngle -1 rad (-57.3 deg) break "
                       "0 <= innerConeAngle < outerConeAngle <= pi/2",
                       Error);
  CHECK_THROWS_WITH_AS(loadJson(withLight({{"type", "spot"}, {"spot", {{"outerConeAngle", "wide"}}}})),
                       doctest::Contains("spot.outerConeAngle '\"wide\"' is not a finite number"), Error);
  const Scene spot = loadJson(withLight({{"type", "spot"}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 1.5707963267948966}}}}));
  REQUIRE(spot.lights.size() == 1);
  CHECK(spot.lights[0].kind == LightKind::Spot);
  CHECK(spot.lights[0].spotCutoffDeg == doctest::Approx(90.0f));
  const Scene defaults = loadJson(withLight({{"type", "spot"}, {"spot", nlohmann::json::object()}}));
  CHECK(defaults.lights[0].spotCutoffDeg == doctest::Approx(45.0f));
  CHECK(loadJson(withLight({{"type", "point"}})).lights[0].kind == LightKind::Point);
}

TEST_CASE("glTF bad input: a texture whose sampler does not exist is refused") {
  nlohmann::json j = triangle();
  j["images"] = {{{"uri", dataUri(pngHeader(4, 4))}}};
  j["samplers"] = nlohmann::json::array({nlohmann::json::object()});  // {object()} alone is an object to clang
  j["textures"] = {{{"source", 0}, {"sampler", 5}}};
  CHECK_THROWS_WITH_AS(loadJson(j), "bad.gltf: textures[0]: sampler '5' does not exist (UNRESOLVED_REFERENCE: the file has 1 sampler)", Error);
  j["textures"][0]["sampler"] = 0;
  CHECK_NOTHROW(loadJson(j));
  j["textures"][0].erase("sampler");  // no sampler: repeat wrapping, auto filtering
  CHECK_NOTHROW(loadJson(j));
}

TEST_CASE("glTF samplers: filters and wraps are read per texture, an absent key keeps REPEAT / LINEAR / LINEAR_MIPMAP_LINEAR") {
  const Scene scene = loadGltf(std::string(FACET_ASSETS) + "/scenes/textured_wraps.gltf");
  REQUIRE(scene.textures.size() == 3);
  CHECK(scene.textures[0].sampler == Sampler{MagFilter::Nearest, MinFilter::Nearest, Wrap::Repeat, Wrap::Repeat});
  CHECK(scene.textures[1].sampler == Sampler{MagFilter::Linear, MinFilter::Linear, Wrap::ClampToEdge, Wrap::ClampToEdge});
  CHECK(scene.textures[2].sampler == Sampler{MagFilter::Linear, MinFilter::Linear, Wrap::MirroredRepeat, Wrap::MirroredRepeat});
  // Each texture has its mipmaps: 8x8 -> 4x4, 2x2, 1x1.
  for (const Texture& t : scene.textures) {
    REQUIRE(t.levelCount() == 4);
    CHECK(t.level(3).width() == 1);
  }
  const Scene box = loadGltf(kModels + "/BoxTextured-glTF/BoxTextured.gltf");
  CHECK(box.textures[0].sampler == Sampler{MagFilter::Linear, MinFilter::NearestMipmapLinear, Wrap::MirroredRepeat, Wrap::ClampToEdge});
  nlohmann::json j = triangle();
  j["images"] = {{{"uri", dataUri(pngHeader(4, 4))}}};
  j["samplers"] = {{{"wrapS", 33071}}};
  j["textures"] = {{{"source", 0}, {"sampler", 0}}, {{"source", 0}}};
  j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}}};
  const Scene partial = loadJson(j);
  CHECK(partial.textures[0].sampler == Sampler{MagFilter::Linear, MinFilter::LinearMipmapLinear, Wrap::ClampToEdge, Wrap::Repeat});
  CHECK(partial.textures[1].sampler == Sampler{});
}

TEST_CASE("glTF bad input: a sampler code outside glTF's lists, or a material's texture that does not exist, is refused by name") {
  nlohmann::json j = triangle();
  j["images"] = {{{"uri", dataUri(pngHeader(4, 4))}}};
  j["textures"] = {{{"source", 0}, {"sampler", 0}}};
  j["samplers"] = {{{"magFilter", 9987}}};
  CHECK_THROWS_WITH_AS(loadJson(j), "bad.gltf: samplers[0]: magFilter '9987' is not one of NEAREST (9728), LINEAR (9729)", Error);
  j["samplers"] = {{{"name", "edge"}, {"wrapT", "REPEAT"}}};
  CHECK_THROWS_WITH_AS(loadJson(j), "bad.gltf: samplers[0] 'edge': wrapT '\"REPEAT\"' is not one of REPEAT (10497), CLAMP_TO_EDGE (33071), MIRRORED_REPEAT (33648)",
                       Error);
  j["samplers"] = {{{"minFilter", -9729}}};
  CHECK_THROWS_WITH_AS(loadJson(j), doctest::Contains("samplers[0]: minFilter '-9729' is not one of NEAREST (9728), LINEAR (9729), NEAREST_MIPMAP_NEAREST"), Error);
  j["samplers"] = {{{"minFilter", 9986}, {"magFilter", 9728}, {"wrapS", 33648}, {"wrapT", 10497}}};
  CHECK_NOTHROW(loadJson(j));
  // A material naming texture 3 of a file with one, in each of the five places a material names a texture.
  for (const char* where : {"baseColorTexture", "metallicRoughnessTexture"}) {
    j["materials"] = {{{"pbrMetallicRoughness", {{where, {{"index", 3}}}}}}};
    const std::string message =
        "bad.gltf: materials[0]: pbrMetallicRoughness." + std::string(where) + ".index '3' does not exist (UNRESOLVED_REFERENCE: the file has 1 texture)";
    CHECK_THROWS_WITH_AS(loadJson(j), message.c_str(), Error);
  }
  for (const char* where : {"normalTexture", "occlusionTexture", "emissiveTexture"}) {
    j["materials"] = {{{"name", "m"}, {where, {{"index", 1}}}}};
    const std::string message = "bad.gltf: materials[0] 'm': " + std::string(where) + ".index '1' does not exist (UNRESOLVED_REFERENCE: the file has 1 texture)";
    CHECK_THROWS_WITH_AS(loadJson(j), message.c_str(), Error);
  }
  j["materials"] = {{{"emissiveTexture", nlohmann::json::object()}}};
  CHECK_THROWS_WITH_AS(loadJson(j), "bad.gltf: materials[0]: emissiveTexture has no index", Error);
  j["materials"] = {{{"emissiveTexture", {{"index", 0}}}}};
  CHECK_NOTHROW(loadJson(j));
}

TEST_CASE("glTF alphaMode: MASK and its cutoff are read, BLEND is read without a warning, other values are refused by name") {
  const Scene scene = loadGltf(std::string(FACET_ASSETS) + "/scenes/alpha_mask.gltf");
  REQUIRE(scene.materials.size() >= 3);
  CHECK(scene.materials[0].alphaMode == AlphaMode::Mask);
  CHECK(scene.materials[0].alphaCutoff == 0.5f);
  CHECK(scene.materials[1].alphaCutoff == 0.9f);
  CHECK(scene.materials[2].alphaMode == AlphaMode::Mask);  // the ramp: glTF's default cutoff
  CHECK(scene.materials[2].alphaCutoff == 0.5f);
  CHECK(scene.textures[0].image.at(0, 0).a == 0);  // the leaf's corner is transparent
  nlohmann::json j = triangle();
  j["materials"] = {{{"name", "glass"}, {"alphaMode", "BLEND"}}};
  const Scene blend = loadJson(j);
  CHECK(blend.materials[0].alphaMode == AlphaMode::Blend);
  CHECK(blend.warnings.empty());
  j["materials"] = {{{"name", "glass"}, {"alphaMode", "mask"}}};
  CHECK_THROWS_WITH_AS(loadJson(j), "bad.gltf: materials[0] 'glass': alphaMode '\"mask\"' is not one of OPAQUE, MASK, BLEND", Error);
  j["materials"] = {{{"alphaMode", "MASK"}, {"alphaCutoff", -0.5}}};
  CHECK_THROWS_WITH_AS(loadJson(j), "bad.gltf: materials[0]: alphaCutoff '-0.5' is not a finite number of at least 0", Error);
  j["materials"] = {{{"alphaMode", "MASK"}, {"alphaCutoff", "half"}}};
  CHECK_THROWS_WITH_AS(loadJson(j), doctest::Contains("alphaCutoff '\"half\"' is not a finite number"), Error);
}

TEST_CASE("glTF KHR_texture_transform on the base colour texture: offset, rotation and scale are read, a bad value is refused by name") {
  const Scene scene = loadGltf(std::string(FACET_ASSETS) + "/scenes/texture_transform.gltf");
  REQUIRE(scene.materials.size() >= 4);
  CHECK(scene.materials[0].baseColorTransform.identity());
  CHECK(scene.materials[1].baseColorTransform.offset == glm::vec2(0.5f, 0.0f));
  CHECK(scene.materials[2].baseColorTransform.rotation == doctest::Approx(1.5707964f));
  CHECK(scene.materials[3].baseColorTransform.scale == glm::vec2(2.0f, 2.0f));
  nlohmann::json j = triangle();
  j["images"] = {{{"uri", dataUri(pngHeader(4, 4))}}};
  j["textures"] = {{{"source", 0}}};
  j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"rotation", "a quarter"}}}}}}}}}}};
  CHECK_THROWS_WITH_AS(loadJson(j), doctest::Contains("materials[0]: baseColorTexture.extensions.KHR_texture_transform: rotation is not a finite number"), Error);
  j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {{"scale", {2}}};
  CHECK_THROWS_WITH_AS(loadJson(j), doctest::Contains("KHR_texture_transform: scale is not an array of two numbers"), Error);
}

TEST_CASE("glTF KHR_materials_emissive_strength multiplies emissiveFactor (after its clamp to 0..1), and a negative strength is ignored") {
  nlohmann::json j = triangle();
  j["materials"] = {{{"emissiveFactor", {1.0, 0.5, 0.25}}, {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}}};
  const Scene strong = loadJson(j);
  CHECK(strong.materials[0].emissive == glm::vec3(4.0f, 2.0f, 1.0f));
  j["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = -2.0;
  CHECK(loadJson(j).materials[0].emissive == glm::vec3(1.0f, 0.5f, 0.25f));
  j["materials"][0]["extensions"].erase("KHR_materials_emissive_strength");
  CHECK(loadJson(j).materials[0].emissive == glm::vec3(1.0f, 0.5f, 0.25f));
}

TEST_CASE("glTF KHR_materials_transmission, _ior and _volume: what the ray tracer refracts, out-of-range values ignored, wrong types refused") {
  nlohmann::json j = triangle();
  j["materials"] = {{{"extensions",
                      {{"KHR_materials_transmission", {{"transmissionFactor", 0.75}}},
                       {"KHR_materials_ior", {{"ior", 1.33}}},
                       {"KHR_materials_volume", {{"attenuationDistance", 2.0}, {"attenuationColor", {0.5, 0.25, 1.0}}}}}}}};
  const Scene glass = loadJson(j);
  CHECK(glass.materials[0].transmission == 0.75f);
  CHECK(glass.materials[0].ior == 1.33f);
  CHECK(glass.materials[0].attenuationDistance == 2.0f);
  CHECK(glass.materials[0].attenuationColor == glm::vec3(0.5f, 0.25f, 1.0f));
  // σ = -ln(c)/d per channel: half the light left after 2 units is ln 2 / 2.
  const CourseMaterial course = courseMaterial(glass.materials[0], {});
  CHECK(course.absorption.x == doctest::Approx(std::log(2.0) / 2.0));
  CHECK(course.absorption.z == 0.0f);
  CHECK(course.transmission == 0.75f);
  MaterialOverrides overrides;
  overrides.transmission = 0.2f, overrides.ior = 2.0f, overrides.reflectivity = 0.5f;
  CHECK(courseMaterial(glass.materials[0], overrides).ior == 2.0f);
  CHECK(courseMaterial(glass.materials[0], overrides).transmission == 0.2f);
  CHECK(courseMaterial(glass.materials[0], overrides).reflectivity == 0.5f);

  j["materials"][0]["extensions"]["KHR_materials_transmission"]["transmissionFactor"] = 1.5;
  j["materials"][0]["extensions"]["KHR_materials_ior"]["ior"] = 0.5;
  j["materials"][0]["extensions"]["KHR_materials_volume"]["attenuationDistance"] = -1.0;
  const Scene odd = loadJson(j);
  CHECK(odd.materials[0].transmission == 0.0f);
  CHECK(odd.materials[0].ior == 1.5f);
  CHECK(std::isinf(odd.materials[0].attenuationDistance));
  CHECK(hasWarning(odd, "materials[0]: KHR_materials_transmission.transmissionFactor 1.500000 is not in [0, 1]; ignored"));
  CHECK(hasWarning(odd, "materials[0]: KHR_materials_ior.ior 0.500000 is neither 0 nor 1 or more; ignored"));

  j["materials"][0]["extensions"]["KHR_materials_ior"]["ior"] = "glass";
  CHECK_THROWS_WITH_AS(loadJson(j), doctest::Contains("materials[0]: KHR_materials_ior.ior is not a number"), Error);
  j["materials"][0]["extensions"]["KHR_materials_ior"]["ior"] = 1.5;
  j["materials"][0]["extensions"]["KHR_materials_volume"]["attenuationColor"] = {1, 1};
  CHECK_THROWS_WITH_AS(loadJson(j), doctest::Contains("KHR_materials_volume.attenuationColor is not an array of three numbers"), Error);
  // Files that require them load.
  j["materials"][0]["extensions"]["KHR_materials_volume"]["attenuationColor"] = {1, 1, 1};
  j["extensionsRequired"] = {"KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume"};
  j["extensionsUsed"] = j["extensionsRequired"];
  CHECK_NOTHROW(loadJson(j));
}

TEST_CASE("glTF KHR_materials_unlit is supported: used or required, it loads without a warning and the material is unlit") {
  nlohmann::json j = triangle();
  j["materials"] = {{{"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}}};
  j["meshes"][0]["primitives"][0]["material"] = 0;
  j["extensionsUsed"] = {"KHR_materials_unlit"};
  j["extensionsRequired"] = {"KHR_materials_unlit"};
  const Scene scene = loadJson(j, "unlit.gltf");
  CHECK(scene.warnings.empty());
  REQUIRE(scene.materials.size() == 1);
  CHECK(scene.materials[0].unlit);
  CHECK(scene.triangleCount() == 1);
}

TEST_CASE("glTF KHR_materials_ior's ior 0 is valid: an infinite index, whose Fresnel term reflects all light at every angle") {
  nlohmann::json j = triangle();
  j["materials"] = {{{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}, {"KHR_materials_ior", {{"ior", 0}}}}}}};
  j["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_ior"};
  const Scene scene = loadJson(j, "mirror.gltf");
  CHECK(scene.warnings.empty());
  REQUIRE(scene.materials.size() == 1);
  CHECK(std::isinf(scene.materials[0].ior));
  CHECK(std::isinf(courseMaterial(scene.materials[0], {}).ior));
  // Entering or leaving, at any angle: F = 1, nothing is transmitted.
  const float inf = std::numeric_limits<float>::infinity();
  for (const float c : {0.0f, 0.5f, 1.0f}) {
    CHECK(ray::fresnelSchlick(1.0f, inf, c, 1.0f) == 1.0f);
    CHECK(ray::fresnelSchlick(inf, 1.0f, c, c) == 1.0f);
  }
  CHECK_FALSE(ray::refracted(glm::vec3(0, 0, -1), glm::vec3(0, 0, 1), inf, 1.0f));
}

TEST_CASE("glTF bad input: positions that cannot be framed are dropped, naming the accessor, and the rest is framed") {
  // Triangle 0 at the origin, triangle 1 at 3e19 (its bounding radius overflowed float: an empty image), triangle 2 with a NaN.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::string bytes = floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 3e19f, 0, 0, 0, 3e19f, 0, 0, 0, 0, 1, 0, 0, nan, 1, 0});
  nlohmann::json j = triangle();
  j["buffers"][0] = {{"byteLength", bytes.size()}, {"uri", dataUri(bytes)}};
  j["bufferViews"] = {{{"buffer", 0}, {"byteLength", bytes.size()}}};
  j["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 9}, {"type", "VEC3"}}};
  j.erase("animations");
  const Scene scene = loadJson(j);
  CHECK(scene.triangleCount() == 1);
  CHECK(hasWarning(scene, "meshes[0].primitives[0]: POSITION accessors[0] has 2 positions beyond +-1e+18, farther than facet draws; their triangles dropped"));
  CHECK(hasWarning(scene, "meshes[0].primitives[0]: POSITION accessors[0] has 1 NaN or infinite position (ACCESSOR_INVALID_FLOAT); their triangles dropped"));
  const Bounds b = scene.worldBounds();
  CHECK(b.max.x == 1.0f);
  CHECK(b.radius() == doctest::Approx(0.7071f));
  // A node that places a mesh beyond the limit: that instance is skipped, the others drawn.
  nlohmann::json far = triangle();
  far["nodes"] = {{{"mesh", 0}}, {{"mesh", 0}, {"scale", {1e30, 1, 1}}}};
  far["scenes"][0]["nodes"] = {0, 1};
  const Scene placed = loadJson(far);
  CHECK(placed.instances.size() == 1);
  CHECK(hasWarning(placed, "nodes[1]: places meshes[0] beyond +-1e+18, farther than facet draws; that instance is skipped"));
}

TEST_CASE("glTF bad input: a bounding box beyond 1.8e19 keeps a finite radius") {
  Bounds b;
  b.include(glm::vec3(-1e19f, -1e19f, 0.0f));
  b.include(glm::vec3(1e19f, 1e19f, 0.0f));
  CHECK(b.radius() == doctest::Approx(1.41421e19f));
  b.include(glm::vec3(3.3e38f, 3.3e38f, 0.0f));
  b.include(glm::vec3(-3.3e38f, -3.3e38f, 0.0f));
  CHECK(std::isinf(b.radius()));  // beyond float: said so, not wrapped
}

TEST_CASE("COLOR_0: float RGB, normalized unsigned byte RGBA and unsigned short RGBA read as the same linear colours") {
  const Scene scene = loadGltf(std::string(FACET_TEST_DATA) + "/../../assets/scenes/vertex_colors.gltf");
  CHECK(scene.warnings.empty());
  int coloured = 0;
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.colors.empty()) continue;
    ++coloured;
    CAPTURE(mesh.name);
    REQUIRE(mesh.colors.size() == 24);
    CHECK(mesh.colors[0] == glm::vec4(1, 0, 0, 1));   // the first face red: 1.0, 255/255, 65535/65535
    CHECK(mesh.colors[4] == glm::vec4(0, 1, 0, 1));   // the second green
    CHECK(mesh.colors[23] == glm::vec4(1, 0, 1, 1));  // the last magenta
  }
  CHECK(coloured == 3);
}

TEST_CASE("material maps: metallic-roughness and occlusion textures are data, emissive ones colour, and their mips follow") {
  const Scene scene = loadGltf(std::string(FACET_TEST_DATA) + "/../../assets/scenes/pbr_maps.gltf");
  CHECK(scene.warnings.empty());
  REQUIRE(scene.materials.size() == 4);
  CHECK(scene.materials[0].metallicRoughnessTexture == 0);
  CHECK(scene.materials[1].occlusionTexture == 1);
  CHECK(scene.materials[1].occlusionStrength == 1.0f);
  CHECK(scene.materials[2].emissiveTexture == 2);
  REQUIRE(scene.textures.size() == 3);
  CHECK(scene.textures[0].encoding == TexelEncoding::Linear);
  CHECK(scene.textures[1].encoding == TexelEncoding::Linear);
  CHECK(scene.textures[2].encoding == TexelEncoding::Srgb);
  // The metallic-roughness map's 1×1 level is the byte average of its roughness ramp, not an sRGB one.
  const Rgba8 last = scene.textures[0].level(scene.textures[0].levelCount() - 1).at(0, 0);
  CHECK(last.b == 128);           // half the texels metallic 255, half 0
  CHECK(std::abs(last.g - 127) <= 1);  // the ramp 0..255..0 averages to half
}

TEST_CASE("material maps: a texture used both as colour and as data is read as colour, with a warning naming it") {
  const Scene scene = loadJson([] {
    nlohmann::json d = nlohmann::json::parse(asset([](nlohmann::json&) {}, false));
    d["images"] = {{{"uri", dataUri(pngHeader(1, 1))}}};
    d["textures"] = {{{"source", 0}}};
    d["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 0}}}}}}};
    return d;
  }());
  CHECK(hasWarning(scene, "textures[0]: used both as a colour (sRGB) and as data (linear); read as colour everywhere"));
}

TEST_CASE("normal textures: tangents from the file's TANGENT, or computed along increasing s with w for a mirrored layout") {
  const Scene scene = loadGltf(std::string(FACET_TEST_DATA) + "/../../assets/scenes/normal_map.gltf");
  CHECK(scene.warnings.empty());
  int tangentMeshes = 0;
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.tangents.empty()) continue;
    ++tangentMeshes;
    REQUIRE(mesh.tangents.size() == mesh.positions.size());
    for (std::size_t v = 0; v < mesh.tangents.size(); ++v) {
      const glm::vec3 T(mesh.tangents[v]);
      CHECK(std::fabs(glm::length(T) - 1.0f) < 1e-5f);
      CHECK(std::fabs(glm::dot(T, mesh.normals[v])) < 1e-5f);
      CHECK(std::fabs(mesh.tangents[v].w) == 1.0f);
    }
  }
  CHECK(tangentMeshes == 3);  // the ground has no normal texture and gets none
  // A quad with s to the right and t down the image (glTF's): T = +x and B = w·(N × T) up the image, +y: w = +1.
  // With s mirrored, T = -x and B still up: w = -1.
  Mesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.normals.assign(4, {0, 0, 1});
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.texcoords = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};  // glTF's t grows downward
  computeVertexTangents(quad);
  CHECK(quad.tangents[0] == glm::vec4(1, 0, 0, 1));  // what the panel's TANGENT in normal_map.gltf says, as exporters write it
  quad.texcoords = {{1, 1}, {0, 1}, {0, 0}, {1, 0}};
  computeVertexTangents(quad);
  CHECK(quad.tangents[0] == glm::vec4(-1, 0, 0, -1));
}

TEST_CASE("glTF bad input: a value of the wrong JSON type is refused by name, not read as absent (assimp's wrongTypes)") {
  const auto refused = [](const std::function<void(nlohmann::json&)>& change, const std::string& message) {
    nlohmann::json j = triangle();
    change(j);
    CHECK_THROWS_WITH_AS(loadJson(j), doctest::Contains(message.c_str()), Error);
  };
  refused([](nlohmann::json& j) { j["meshes"][0]["primitives"] = {{"mode", 4}}; }, "bad.gltf: meshes[0]: primitives '{\"mode\":4}' is not an array");
  refused([](nlohmann::json& j) { j["meshes"][0]["primitives"] = nlohmann::json::array(); }, "primitives '[]' is not an array of one or more");
  refused([](nlohmann::json& j) { j["meshes"][0]["primitives"][0].erase("attributes"); }, "meshes[0]: primitives[0]: attributes is missing");
  refused([](nlohmann::json& j) { j["materials"] = {{{"pbrMetallicRoughness", {"not an object"}}}}; },
          "materials[0]: pbrMetallicRoughness '[\"not an object\"]' is not a JSON object");
  refused([](nlohmann::json& j) { j["materials"] = {{{"normalTexture", {{"index", 0}, {"scale", "big"}}}}}; },
          "materials[0]: normalTexture.scale '\"big\"' is not a number");
  refused([](nlohmann::json& j) { j["materials"] = {{{"pbrMetallicRoughness", {{"metallicFactor", "1"}}}}}; },
          "pbrMetallicRoughness.metallicFactor '\"1\"' is not a number");
  refused([](nlohmann::json& j) { j["materials"] = {{{"emissiveTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", "no"}}}}}}}; },
          "materials[0].emissiveTexture.extensions.'KHR_texture_transform' '\"no\"' is not a JSON object");
  refused([](nlohmann::json& j) { j["scenes"][0]["name"] = 42; }, "scenes[0]: name '42' is not a string");
  refused([](nlohmann::json& j) { j["scene"] = "hello"; }, "scene '\"hello\"' does not exist (UNRESOLVED_REFERENCE: the file has 1 scene)");
  refused([](nlohmann::json& j) { j.erase("scenes"), j["scene"] = 0; }, "scene '0' does not exist (UNRESOLVED_REFERENCE: the file has 0 scenes)");
  refused([](nlohmann::json& j) { j["nodes"] = {{"mesh", 0}}; }, "nodes '{\"mesh\":0}' is not an array");
  refused([](nlohmann::json& j) { j["nodes"][0] = 7; }, "nodes[0] '7' is not a JSON object");
  // What glTF allows stays allowed: extras of any type, an extension with members.
  nlohmann::json j = triangle();
  j["extras"] = {{"extensions", 5}};
  j["nodes"][0]["extras"] = "anything";
  CHECK_NOTHROW(loadJson(j));
}

TEST_CASE("glTF texCoord: each texture reference reads TEXCOORD_0 or TEXCOORD_1, tangents follow the normal texture's set") {
  const Scene scene = loadGltf(std::string(FACET_TEST_DATA) + "/../../assets/scenes/texcoord_sets.gltf");
  const auto mesh = [&](const std::string& name) -> const Mesh& {
    for (const Mesh& m : scene.meshes)
      if (m.name == name) return m;
    FAIL("no mesh " << name);
    return scene.meshes.front();
  };
  const Mesh& cube = mesh("cube");
  REQUIRE(cube.texcoords.size() == 24);
  REQUIRE(cube.texcoords1.size() == 24);
  CHECK(cube.texcoords[1] == 3.0f * cube.texcoords1[1]);  // the bricks repeat three times on set 0
  const TexcoordSets& sets = scene.materials[static_cast<std::size_t>(cube.material)].texcoordSets;
  CHECK(sets.baseColor == 0);
  CHECK((sets.occlusion == 1 && sets.emissive == 1 && sets.normal == 1 && sets.metallicRoughness == 0));
  CHECK(cube.tangents.size() == 24);
  const Mesh& only1 = mesh("TEXCOORD_1 only");
  CHECK((only1.texcoords.empty() && only1.texcoords1.size() == 4));
  CHECK(mesh("no TEXCOORD_1").texcoords1.empty());
  CHECK(hasWarning(scene, "meshes[3].primitives[0]: materials[3]'s baseColorTexture reads TEXCOORD_1, which the primitive does not have; not read"));
  CHECK(scene.warnings.size() == 1);

  // Tangents from set 1 where it turns against set 0: s of set 1 runs up the quad, so T = +y.
  Mesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.normals.assign(4, {0, 0, 1});
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.texcoords = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  quad.texcoords1 = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  computeVertexTangents(quad, 1);
  CHECK(glm::vec3(quad.tangents[0]) == glm::vec3(0, 1, 0));
  computeVertexTangents(quad, 0);
  CHECK(glm::vec3(quad.tangents[0]) == glm::vec3(1, 0, 0));

  // texCoord 2 and beyond: TEXCOORD_0, with a warning naming the material and the key.
  std::ifstream file(std::string(FACET_TEST_DATA) + "/../../assets/scenes/texcoord_sets.gltf");
  nlohmann::json j = nlohmann::json::parse(file);
  j["materials"][0]["occlusionTexture"]["texCoord"] = 2;
  const Scene two = loadGltfFromMemory(j.dump(), "sets.gltf", "");
  CHECK(two.materials[0].texcoordSets.occlusion == 0);
  CHECK(hasWarning(two, "materials[0]: occlusionTexture uses TEXCOORD_2; facet reads TEXCOORD_0 and TEXCOORD_1, and TEXCOORD_0 is used instead"));
}

TEST_CASE("glTF POINTS, LINES, LINE_LOOP and LINE_STRIP load as points and segments, and an unknown mode is skipped by name") {
  const auto load = [](int mode) {
    return loadGltfFromMemory(asset([&](nlohmann::json& j) { j["meshes"][0]["primitives"][0]["mode"] = mode; }, false), "modes.gltf", "");
  };
  const Scene points = load(0), lines = load(1), loop = load(2), strip = load(3), fan = load(6);
  REQUIRE(points.meshes.size() == 1);
  CHECK(points.meshes[0].points == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(points.meshes[0].indices.empty());
  CHECK(points.meshes[0].normals.size() == 3);  // unlit, but every vertex has one
  CHECK(lines.meshes[0].lines == std::vector<std::uint32_t>{0, 1});
  CHECK(hasWarning(lines, "3 indices is not a multiple of 2; the last 1 ignored"));
  CHECK(loop.meshes[0].lines == std::vector<std::uint32_t>{0, 1, 1, 2, 2, 0});
  CHECK(strip.meshes[0].lines == std::vector<std::uint32_t>{0, 1, 1, 2});
  CHECK(fan.meshes[0].indices == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(fan.meshes[0].lines.empty());
  const Scene unknown = load(7);
  CHECK(unknown.meshes.empty());
  CHECK(hasWarning(unknown, "meshes[0].primitives[0]: mode 7 is not a glTF primitive mode (0 to 6); skipped"));

  // The sample's LINE_LOOP with indices [0, 3, 2, 1]: four segments, closed.
  const Scene sample = loadScene(kModels + "/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_09.gltf");
  REQUIRE(sample.meshes.size() == 1);
  CHECK(sample.meshes[0].lines == std::vector<std::uint32_t>{0, 3, 3, 2, 2, 1, 1, 0});
  const Scene many = loadScene(kModels + "/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_07.gltf");
  REQUIRE(many.meshes.size() == 1);
  CHECK(many.meshes[0].points.size() == 1024);
}

TEST_CASE("glTF loader: particle emitters from node extras, placed in the node's frame") {
  const Scene scene = loadScene(std::string(FACET_ASSETS) + "/particles.gltf");
  REQUIRE(scene.emitters.size() == 3);
  const Emitter& fountain = scene.emitters[0];
  CHECK(fountain.position.x == doctest::Approx(-1.4f));
  CHECK(fountain.position.y == doctest::Approx(0.22f));
  CHECK(fountain.rate == 600.0f);
  CHECK(fountain.seed == 3);
  CHECK(scene.emitters[1].blending == SpriteBlending::Additive);
  CHECK_FALSE(scene.emitters[1].ground);
  // The smoke's node is turned -20 degrees about x: its emitter's +y leans toward -z.
  const glm::vec3 d = glm::normalize(scene.emitters[2].direction);
  CHECK(d.y == doctest::Approx(std::cos(glm::radians(20.0f))));
  CHECK(d.z == doctest::Approx(-std::sin(glm::radians(20.0f))));
}
