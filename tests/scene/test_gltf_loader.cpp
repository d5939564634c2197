// The glTF loader on Debian's assimp-testmodels files.
#include <string>

#include <doctest/doctest.h>

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
