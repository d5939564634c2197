// The frame's spine (pipeline/frame_spine.h): what the settings add goes into
// scenes of the spine's own, never into the loaded scene; the files they
// name are read once per spine; frames that add the same share one scene;
// sprites face each frame's camera.
#include <filesystem>
#include <memory>
#include <string>

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "common/error.h"
#include "pipeline/frame_spine.h"
#include "scene/default_scene.h"
#include "scene/load_scene.h"
#include "scratch_folder.h"

using namespace facet;
namespace fs = std::filesystem;

namespace {

const std::string kAssets = FACET_ASSETS;

RenderSettings small() {
  RenderSettings s;
  s.width = 48;
  s.height = 36;
  s.shadows.mapSize = 64;
  return s;
}

// The settings' every addition: the three material maps, the volume's iso-surface, a particle emitter.
RenderSettings everything(const std::string& heights, const std::string& sky) {
  RenderSettings s = small();
  s.material.displacementMap = heights;
  s.material.displacementSubdivisions = 1;
  s.material.bumpMap = heights;
  s.environment.map = sky;
  s.volume.file = "builtin:marschner-lobb";
  s.volume.resolution = 8;
  s.volume.mode = VolumeMode::Isosurface;
  s.particles = {Emitter{}};
  s.time = 1.0f;
  return s;
}

// The first sprite's facing: the unit normal of its quad's first triangle.
glm::vec3 spriteFacing(const Scene& scene, const std::string& name) {
  for (const Mesh& mesh : scene.meshes)
    if (mesh.name == name && mesh.indices.size() >= 3) {
      const glm::vec3 a = mesh.positions[mesh.indices[0]], b = mesh.positions[mesh.indices[1]], c = mesh.positions[mesh.indices[2]];
      return glm::normalize(glm::cross(b - a, c - a));
    }
  FAIL("no sprites named " << name);
  return glm::vec3(0.0f);
}

}  // namespace

TEST_CASE("spine: the loaded scene is left as it was by a frame with material maps, a volume and particles") {
  const auto loaded = std::make_shared<const Scene>(loadScene(kAssets + "/bump.gltf"));
  const Scene before = *loaded;  // a copy to hold it against
  const std::weak_ptr<const char> token = loaded->identity.token();

  FrameSpine spine(loaded);
  const PreparedFrame frame = spine.frame(everything(kAssets + "/displacement/height.png", kAssets + "/environment/sky_cube.png"));

  // The frame drew all of it, from a scene of its own.
  CHECK(frame.scene != loaded);
  CHECK(frame.added.isosurface);
  CHECK(frame.added.particles > 0);
  CHECK_FALSE(frame.scene->displacement.empty());
  CHECK(frame.scene->bumpMapPath == kAssets + "/displacement/height.png");
  CHECK(frame.inputs.environment.map == &frame.scene->environment);
  CHECK(frame.scene->triangleCount() > before.triangleCount());

  // The loaded scene: the same content, and no renewed identity (what a change in place does).
  CHECK(loaded->identity.is(token));
  REQUIRE(loaded->meshes.size() == before.meshes.size());
  for (std::size_t m = 0; m < before.meshes.size(); ++m) {
    CAPTURE(m);
    CHECK(loaded->meshes[m].positions == before.meshes[m].positions);
    CHECK(loaded->meshes[m].normals == before.meshes[m].normals);
    CHECK(loaded->meshes[m].tangents == before.meshes[m].tangents);
    CHECK(loaded->meshes[m].indices == before.meshes[m].indices);
  }
  CHECK(loaded->instances.size() == before.instances.size());
  CHECK(loaded->materials.size() == before.materials.size());
  CHECK(loaded->textures.size() == before.textures.size());
  CHECK(loaded->warnings == before.warnings);
  CHECK(loaded->displacement.empty());
  CHECK(loaded->bumpMapPath.empty());
  CHECK(loaded->environment.empty());
  CHECK_FALSE(loaded->volume.data);
  CHECK(loaded->unmeshed.empty);
}

TEST_CASE("spine: a frame that adds nothing draws the loaded scene itself, and frames that add the same share one scene") {
  const auto loaded = std::make_shared<const Scene>(makeDefaultScene());
  FrameSpine spine(loaded);
  CHECK(spine.frame(small()).scene == loaded);

  RenderSettings iso = small();
  iso.volume.file = "builtin:marschner-lobb";
  iso.volume.resolution = 8;
  const PreparedFrame first = spine.frame(iso);
  CHECK(first.scene != loaded);
  // Another camera, another size: the same iso-surface, so the same scene (a GL backend uploads it once).
  RenderSettings moved = iso;
  moved.width = 40;
  const PreparedFrame second = spine.frame(moved, CameraOrbit{30.0, 10.0, 1.5});
  CHECK(second.scene == first.scene);
  CHECK(second.added.isosurface);
  CHECK(second.added.isoTriangles == first.added.isoTriangles);
  // Another iso value is another mesh: a scene of its own.
  moved.volume.isoValue = 0.25f;
  CHECK(spine.frame(moved).scene != first.scene);
}

TEST_CASE("spine: two frames of one spine read the volume once, and another resolution reads it again") {
  FrameSpine spine(std::make_shared<const Scene>(makeDefaultScene()));
  RenderSettings settings = small();
  settings.volume.file = "builtin:marschner-lobb";
  settings.volume.resolution = 8;
  settings.volume.mode = VolumeMode::Raycast;
  const PreparedFrame first = spine.frame(settings);
  REQUIRE(first.scene->volume.data);

  // Another mode, time and camera: the samples read for the first frame, not read again.
  settings.volume.mode = VolumeMode::Isosurface;
  settings.time = 2.0f;
  const PreparedFrame second = spine.frame(settings, CameraOrbit{90.0, 0.0, 1.0});
  CHECK(second.scene->volume.data == first.scene->volume.data);

  settings.volume.resolution = 9;
  const PreparedFrame third = spine.frame(settings);
  CHECK(third.scene->volume.data != first.scene->volume.data);
  CHECK(third.scene->volume.data->size.x == 9);
}

TEST_CASE("spine: the map files are read once per spine, and frames naming them draw after the files are gone") {
  const fs::path folder = test::scratchFolder("frame_spine", "read_once");
  const std::string heights = (folder / "height.png").string(), sky = (folder / "sky.png").string();
  fs::copy_file(kAssets + "/displacement/height.png", heights);
  fs::copy_file(kAssets + "/environment/sky_cube.png", sky);
  const auto loaded = std::make_shared<const Scene>(loadScene(kAssets + "/bump.gltf"));
  FrameSpine spine(loaded);
  RenderSettings settings = everything(heights, sky);
  const PreparedFrame first = spine.frame(settings);
  fs::remove(heights);
  fs::remove(sky);

  // Another displacement scale makes the maps' scene anew, from the maps read for the first frame.
  settings.material.displacementScale = 0.2f;
  const PreparedFrame second = spine.frame(settings);
  CHECK(second.scene != first.scene);
  CHECK(second.scene->environment.faces == first.scene->environment.faces);
  CHECK(second.scene->bumpMap.image == first.scene->bumpMap.image);
  // A spine of its own has read nothing: the files are gone, and the error names the key.
  CHECK_THROWS_WITH_AS(FrameSpine(loaded).frame(settings), doctest::Contains("material.displacementMap: "), Error);
}

TEST_CASE("spine: sprites are added for each frame, facing that frame's camera") {
  const auto loaded = std::make_shared<const Scene>(makeDefaultScene());
  FrameSpine spine(loaded);
  RenderSettings settings = small();
  settings.particles = {Emitter{}};
  settings.time = 1.0f;
  const std::string sprites = "particles of particles.0";

  const PreparedFrame ahead = spine.frame(settings);
  const PreparedFrame turned = spine.frame(settings, CameraOrbit{90.0, 20.0, 1.0});
  CHECK(turned.scene != ahead.scene);
  CHECK(turned.settings.camera.source == Source::Manual);  // resolved before the sprites were made to face it
  for (const PreparedFrame* frame : {&ahead, &turned}) {
    const glm::vec3 facing = spriteFacing(*frame->scene, sprites);
    CHECK(glm::dot(facing, frame->inputs.towardEye) == doctest::Approx(1.0f).epsilon(1e-3));
  }
  CHECK(glm::dot(ahead.inputs.towardEye, turned.inputs.towardEye) < 0.9f);  // the two views differ

  // A new time: the particles have moved, into a scene of that frame's.
  settings.time = 1.5f;
  const PreparedFrame later = spine.frame(settings);
  CHECK(later.scene != ahead.scene);
  CHECK(later.added.particles != ahead.added.particles);
  CHECK(loaded->meshes.size() == makeDefaultScene().meshes.size());
}
