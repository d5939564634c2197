// The settings panel: the auto-to-manual rule of an edit, and a whole panel
// drawn by Dear ImGui with no window and no renderer (the visitor must give
// every field of the table a control; an ImGui assertion fails the test).
#include <doctest/doctest.h>
#include <imgui.h>

#include "pipeline/view_setup.h"
#include "scene/default_scene.h"
#include "scene/primitives.h"
#include "viewer/settings_panel.h"

using namespace facet;
using namespace facet::viewer;

namespace {

// A scene without camera or lights: auto fits both to it.
Scene cubeScene() {
  Scene scene;
  scene.meshes.push_back(makeCube());
  scene.instances.push_back({0, glm::mat4(1.0f)});
  return scene;
}

bool sameCamera(const CameraSettings& a, const CameraSettings& b) {
  return a.source == b.source && a.eye == b.eye && a.reference == b.reference && a.up == b.up && a.projection == b.projection &&
         a.halfAngleDeg == b.halfAngleDeg && a.parallelWidth == b.parallelWidth && a.near == b.near && a.far == b.far;
}

// An ImGui context of its own for one test, with a font atlas and a display
// but no platform or renderer backend.
class HeadlessImGui {
 public:
  HeadlessImGui() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1280.0f, 800.0f);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  }
  ~HeadlessImGui() { ImGui::DestroyContext(); }

  // One frame with the panel in a window; what drawSettingsPanel returned.
  bool drawPanel(RenderSettings& settings, const Scene& scene) {
    ImGui::NewFrame();
    ImGui::SetNextWindowSize(ImVec2(420.0f, 800.0f));
    ImGui::Begin("settings");
    const bool changed = drawSettingsPanel(settings, scene, sceneSphere(scene));
    ImGui::End();
    ImGui::Render();
    return changed;
  }
};

}  // namespace

TEST_CASE("an auto camera and auto lights are shown as auto chose them, still auto") {
  const Scene scene = cubeScene();
  const RenderSettings settings;
  const RenderSettings shown = shownSettings(scene, settings);
  CameraSettings expected = resolveCamera(scene, settings);
  expected.source = Source::Auto;
  CHECK(sameCamera(shown.camera, expected));
  CHECK(shown.lightSource == Source::Auto);
  REQUIRE(shown.lights.size() == 1);
  CHECK(shown.lights[0].position == resolveLights(scene, settings)[0].position);
}

TEST_CASE("an edit outside the camera and the lights leaves them auto, with their own values") {
  const Scene scene = cubeScene();
  const RenderSettings settings;
  RenderSettings shown = shownSettings(scene, settings);
  shown.shading = ShadingMode::Flat;
  const RenderSettings edited = editedSettings(settings, shown, "shading", sceneSphere(scene));
  CHECK(edited.shading == ShadingMode::Flat);
  CHECK(sameCamera(edited.camera, settings.camera));
  CHECK(edited.lightSource == Source::Auto);
  CHECK(edited.lights.empty());
}

TEST_CASE("editing a camera field of an auto camera makes it manual, from what auto chose") {
  const Scene scene = cubeScene();
  const RenderSettings settings;
  RenderSettings shown = shownSettings(scene, settings);
  const glm::vec3 autoEye = shown.camera.eye;
  shown.camera.near *= 0.5f;
  const RenderSettings edited = editedSettings(settings, shown, "camera.near", sceneSphere(scene));
  CHECK(edited.camera.source == Source::Manual);
  CHECK(edited.camera.eye == autoEye);
  CHECK(edited.camera.near == shown.camera.near);

  shown = shownSettings(scene, settings);
  shown.camera.source = Source::Manual;  // the combo alone
  const RenderSettings switched = editedSettings(settings, shown, "camera.source", sceneSphere(scene));
  CHECK(switched.camera.source == Source::Manual);
  CHECK(switched.camera.eye == autoEye);
}

TEST_CASE("editing a light of auto lights makes the list manual, from what auto chose") {
  const Scene scene = cubeScene();
  const RenderSettings settings;
  RenderSettings shown = shownSettings(scene, settings);
  shown.lights[0].intensity = 2.0f;
  const RenderSettings edited = editedSettings(settings, shown, "lights.0.intensity", sceneSphere(scene));
  CHECK(edited.lightSource == Source::Manual);
  REQUIRE(edited.lights.size() == 1);
  CHECK(edited.lights[0].intensity == 2.0f);
  CHECK(edited.lights[0].position == resolveLights(scene, settings)[0].position);
  CHECK(edited.camera.source == Source::Auto);
}

TEST_CASE("camera.projection toggles: auto stays auto, manual keeps its width of view") {
  const Scene scene = cubeScene();
  RenderSettings settings;
  RenderSettings shown = shownSettings(scene, settings);
  shown.camera.projection = ProjectionKind::Parallel;
  RenderSettings edited = editedSettings(settings, shown, "camera.projection", sceneSphere(scene));
  CHECK(edited.camera.source == Source::Auto);
  CHECK(edited.camera.projection == ProjectionKind::Parallel);

  settings = materialize(scene, RenderSettings{}, true, false);
  shown = shownSettings(scene, settings);
  shown.camera.projection = ProjectionKind::Parallel;
  edited = editedSettings(settings, shown, "camera.projection", sceneSphere(scene));
  CHECK(edited.camera.projection == ProjectionKind::Parallel);
  CHECK(edited.camera.parallelWidth != doctest::Approx(RenderSettings{}.camera.parallelWidth));
}

TEST_CASE("the whole panel draws in an ImGui frame, and leaves settings alone without input") {
  HeadlessImGui imgui;
  const Scene scene = makeDefaultScene();
  RenderSettings settings;
  for (int frame = 0; frame < 3; ++frame) CHECK_FALSE(imgui.drawPanel(settings, scene));

  // Every kind of field in use: manual lights of each kind, overrides on and off.
  settings.lightSource = Source::Manual;
  settings.lights.resize(3);
  settings.lights[1].kind = LightKind::Directional;
  settings.lights[2].kind = LightKind::Spot;
  settings.material.ks = 0.25f;
  settings.camera.source = Source::Manual;
  settings.camera.projection = ProjectionKind::Parallel;
  const RenderSettings before = settings;
  for (int frame = 0; frame < 3; ++frame) CHECK_FALSE(imgui.drawPanel(settings, scene));
  CHECK(settings.lights.size() == before.lights.size());
  CHECK(settings.material.ks == before.material.ks);
  CHECK_FALSE(settings.material.kd.has_value());
}
