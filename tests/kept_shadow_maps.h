#pragma once
// A renderer keeps the shadow maps it drew while what pass 1 reads is
// unchanged (pipeline/shadow_pass_key.h), and draws them again when any of
// it changes: frame after frame, one renderer's images equal those of a
// fresh renderer for each frame. The CPU and GL tests run this scenario.
#include <functional>
#include <memory>
#include <string>

#include <doctest/doctest.h>
#include <glm/ext/matrix_transform.hpp>

#include "pipeline/frame_inputs.h"
#include "pipeline/shadow_pass_key.h"
#include "pipeline/view_setup.h"
#include "render/renderer.h"
#include "scene/default_scene.h"

namespace facet::test {

// The frame's shadow pass timing: "shadow pass (6 maps)" or "... kept)".
inline std::string shadowPassTiming(const RenderResult& result) {
  for (const PassTiming& t : result.timings)
    if (t.pass.rfind("shadow pass", 0) == 0) return t.pass;
  return "none";
}

inline void checkShadowMapsKept(const std::function<std::unique_ptr<Renderer>()>& makeRenderer) {
  auto scene = std::make_unique<Scene>(makeDefaultScene());
  RenderSettings settings;
  settings.width = 96;
  settings.height = 72;
  settings.shadows.mapSize = 256;
  settings = materialize(*scene, settings, true, true);
  const std::unique_ptr<Renderer> renderer = makeRenderer();

  // Draws `frame` with the kept renderer; checks the pass was kept or not, and the image against a fresh renderer's.
  const auto draw = [&](const char* what, const FrameInputs& frame, bool kept) {
    CAPTURE(what);
    const RenderResult result = renderer->render(*scene, frame);
    CHECK(shadowPassTiming(result) == shadowPassName(frame, kept));
    const Image fresh = makeRenderer()->render(*scene, frame).image;
    CHECK(result.image == fresh);
  };
  draw("the first frame", buildFrameInputs(*scene, settings), false);

  settings.camera.eye += glm::vec3(1.5f, 0.5f, -0.5f);
  draw("the camera moved", buildFrameInputs(*scene, settings), true);
  settings.width = 80;
  draw("another image size", buildFrameInputs(*scene, settings), true);

  settings.lights[0].position += glm::vec3(0.7f, 0.0f, 0.4f);
  draw("the light moved", buildFrameInputs(*scene, settings), false);
  draw("the same frame again", buildFrameInputs(*scene, settings), true);

  settings.shadows.mapSize = 128;
  draw("another map size", buildFrameInputs(*scene, settings), false);

  FrameInputs moved = buildFrameInputs(*scene, settings);
  FrameInstance& instance = moved.instances.back();
  const glm::mat4 lift = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.4f, 0.0f));
  instance.worldFromModel = lift * instance.worldFromModel;
  instance.clipFromModel = moved.clipFromWorld * instance.worldFromModel;
  draw("an instance moved (TM)", moved, false);

  FrameInputs unshadowed = moved;
  for (CourseMaterial& material : unshadowed.materials) material.castsShadow = false;
  draw("no material casts a shadow", unshadowed, false);

  settings.material.opacity = 0.4f;  // below transparency.shadowCutoff: blended surfaces cast no shadow
  draw("materials no longer cast shadows", buildFrameInputs(*scene, settings), false);

  scene = std::make_unique<Scene>(*scene);  // the same content, another scene: its meshes may differ
  draw("a scene copy", buildFrameInputs(*scene, settings), false);
}

}  // namespace facet::test
