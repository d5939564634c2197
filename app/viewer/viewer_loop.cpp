// The viewer's main loop, shaped as Dear ImGui's
// examples/example_glfw_opengl3/main.cpp: set up GLFW, OpenGL and ImGui, then
// every frame: events, the ImGui frame (panel and shortcuts edit the
// settings), the 3D frame by the GL backend's Renderer (the one facet render
// uses, on the window's context) into its framebuffer, a blit of it to the
// window, ImGui on top, swap.
#include "viewer/viewer_loop.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include "pipeline/bump_map.h"
#include "pipeline/displacement.h"
#include "pipeline/scene_additions.h"
#include "scene/environment_map.h"
#include "common/error.h"
#include "gl/gl_renderer.h"
#include "image/png.h"
#include "pipeline/frame_inputs.h"
#include "settings/settings_json.h"
#include "viewer/control_panel.h"
#include "viewer/frame_times.h"
#include "viewer/imgui_session.h"
#include "viewer/orbit_bench.h"
#include "viewer/reference_view.h"
#include "viewer/view_input.h"
#include "viewer/viewer_gl.h"
#include "viewer/viewer_state.h"
#include "viewer/viewer_window.h"

namespace facet::viewer {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

// How long an idle window sleeps in glfwWaitEventsTimeout: any input wakes it
// at once; the timeout only paces ImGui's own delays (tooltips).
constexpr double kIdleWaitSeconds = 0.5;
constexpr double kBusyWaitSeconds = 0.02;  // while the CPU reference renders

// An interactive window keeps room for the panel's status lines and a few
// controls; --screenshot windows take any size.
constexpr int kMinimumWindowWidth = 240, kMinimumWindowHeight = 180;

ViewerState initialState(const ViewerOptions& options) {
  ViewerState state;
  setScene(state, options.scene);
  state.scenePath = options.scenePath;
  state.settings = options.settings;
  state.startSettings = options.settings;
  state.settingsPath = options.settingsPath.empty() ? "facet-settings.json" : options.settingsPath;
  state.screenshotPath = options.screenshotPath;
  return state;
}

// Everything the 3D frame depends on: the scene and the settings.
std::string frameKey(const ViewerState& state) { return std::to_string(state.sceneSerial) + settingsToJson(state.settings).dump(); }

// The CPU reference leaves a core to the window (and llvmpipe).
int referenceThreads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency()) - 1); }

// The window's back buffer, panel included: read before the swap, since
// the front buffer reads back as zeros under Xvfb. Opaque, as the GL image is.
Image readWindow(const ViewerGl& gl, int width, int height) {
  Image image(width, height);
  gl.gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  gl.gl.glPixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.gl.glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  gl.gl.glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.at(x, y).a = 255;
  return image;
}

// The 3D frame on screen: what the renderer's framebuffer holds.
struct DrawnFrame {
  std::uint64_t version = 0;           // counts the distinct frames drawn; 0: none yet
  std::string key;                     // frameKey when it was last drawn (or failed to draw)
  std::shared_ptr<const Scene> scene;  // the scene `frame` was built from
  FrameInputs frame;
  Image image;                         // what render() read back
  double milliseconds = 0;             // the frame's passes (upload, shadow, lit; not the read-back), when it last ran
  std::string error;                   // why the newest settings could not be drawn; the last good image stays
  // The viewer's scene displaced and with the settings' environment map, while they and the scene stay.
  std::shared_ptr<const Scene> environmentBase, withEnvironment;
  // The volume the last frame read (pipeline/scene_additions.h), kept so that the next reads it no more.
  std::shared_ptr<const Scene::PlacedVolume> volume;
  std::string volumeKey;
};

// Whether the settings or the scene add a volume or particles to the frame.
bool hasAdditions(const Scene& scene, const RenderSettings& settings) {
  return !settings.volume.file.empty() || !scene.volume.file.empty() || !settings.particles.empty() || !scene.emitters.empty();
}

// The scene a frame of `state` draws: its own when the settings displace
// nothing and name the map it holds (or none), else a copy displaced and
// with that map, made once per displacement and map.
std::shared_ptr<const Scene> sceneFor(const ViewerState& state, DrawnFrame& drawn) {
  const std::string displacement = displacementKey(state.settings.material);
  const auto matches = [&](const Scene& s) {
    return s.environment.path == state.settings.environment.map && s.displacement == displacement && s.bumpMapPath == state.settings.material.bumpMap;
  };
  if (matches(*state.scene)) return state.scene;
  if (drawn.withEnvironment && drawn.environmentBase == state.scene && matches(*drawn.withEnvironment)) return drawn.withEnvironment;
  auto copy = std::make_shared<Scene>(*state.scene);
  useDisplacement(*copy, state.settings.material);
  useBumpMap(*copy, state.settings.material);
  useEnvironment(*copy, state.settings.environment);
  drawn.environmentBase = state.scene;
  drawn.withEnvironment = copy;
  return copy;
}

// Draws the 3D frame when the scene or the settings changed since the last
// one (or always, with force); true when it tried. The renderer uploads a
// scene only when it is not the one it drew last.
bool drawChangedFrame(Renderer& renderer, const ViewerState& state, DrawnFrame& drawn, bool force) {
  const std::string key = frameKey(state);
  if (key == drawn.key && !force) return false;
  try {
    std::shared_ptr<const Scene> scene = sceneFor(state, drawn);
    RenderSettings settings = state.settings;
    if (hasAdditions(*scene, settings)) {
      // A copy with the volume and this time's particles, facing this frame's camera; the volume is read once.
      auto added = std::make_shared<Scene>(*scene);
      if (drawn.volume && drawn.volume->key == drawn.volumeKey) added->volume = *drawn.volume;
      SceneAdditions counts;
      settings = addVolumeAndParticles(*added, settings, counts);
      drawn.volume = std::make_shared<Scene::PlacedVolume>(added->volume);
      drawn.volumeKey = added->volume.key;
      scene = added;
    }
    FrameInputs frame = buildFrameInputs(*scene, settings);
    RenderResult result = renderer.render(*scene, frame);
    drawn.milliseconds = 0;
    for (const PassTiming& t : result.timings)
      if (t.pass != "read-back") drawn.milliseconds += t.milliseconds;
    if (key != drawn.key || drawn.version == 0) ++drawn.version;
    drawn.scene = scene;
    drawn.frame = std::move(frame);
    drawn.image = std::move(result.image);
    drawn.error.clear();
  } catch (const Error& e) {
    drawn.error = e.what();
  }
  drawn.key = key;
  return true;
}

// The renderer's framebuffer into the window's, scaled for the frame
// after a resize, before the new size is drawn.
void blitToWindow(const ViewerGl& gl, const WindowGlRenderer& renderer, const DrawnFrame& drawn, int width, int height) {
  gl.gl.glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  gl.gl.glDisable(GL_SCISSOR_TEST);  // a blit honours the scissor box
  gl.gl.glViewport(0, 0, width, height);
  const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  gl.gl.glClearNamedFramebufferfv(0, GL_COLOR, 0, black);
  if (drawn.version == 0) return;
  gl.glBlitNamedFramebuffer(renderer.framebuffer(), 0, 0, 0, drawn.frame.width, drawn.frame.height, 0, 0, width, height, GL_COLOR_BUFFER_BIT,
                            GL_NEAREST);
}

// In the bottom right corner, when the panel (whose status lines say it) is hidden.
void drawErrorOverlay(const std::string& error) {
  ImGui::SetNextWindowPos(ImGui::GetIO().DisplaySize, ImGuiCond_Always, ImVec2(1.0f, 1.0f));
  ImGui::Begin("frame error", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs);
  ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "cannot draw these settings: %s", error.c_str());
  ImGui::End();
}

}  // namespace

int runViewer(const ViewerOptions& options) {
  ViewerState state = initialState(options);
  const bool bench = options.benchOrbit > 0;
  const bool batch = !options.batchScreenshot.empty() || bench;

  // Setup window, OpenGL 4.5 core, the GL backend and Dear ImGui
  GlfwLibrary glfw;
  ViewerWindow window(state.settings.width, state.settings.height);
  glfwSwapInterval(batch ? 0 : 1);
  if (!batch) window.setMinimumSize(kMinimumWindowWidth, kMinimumWindowHeight);
  const ViewerGl gl = loadViewerGl(glfwGetProcAddress);
  const std::unique_ptr<WindowGlRenderer> rendererOwner = makeWindowGlRenderer(glfwGetProcAddress);
  WindowGlRenderer& renderer = *rendererOwner;
  ImGuiSession imgui(window.handle());
  ReferenceView reference(gl.gl, referenceThreads(), options.followReference, options.rayReference);
  ViewInput input;

  DrawnFrame drawn;
  FrameTimes drawTimes, windowTimes;
  bool showPanel = true;
  bool redrawEveryFrame = false;  // the panel's checkbox
  bool changedLastFrame = false;
  int framesLeft = bench ? options.benchOrbit + 1 : options.frames;  // the bench's first frame (upload, compile) is not timed
  std::vector<double> benchFrames;
  Clock::time_point lastIteration = Clock::now();

  // Main loop
  while (!glfwWindowShouldClose(window.handle())) {
    // Poll and handle events; an idle window waits for them instead of spinning.
    const bool idle = !batch && !state.playing && !changedLastFrame && !reference.busy() && !ImGui::IsAnyMouseDown();
    if (batch && framesLeft > 0) glfwPollEvents();
    else glfwWaitEventsTimeout(idle ? kIdleWaitSeconds : kBusyWaitSeconds);
    const Clock::time_point start = Clock::now();
    // Playing: time advances by the wall clock since the last iteration (at most 0.1 s, so a stall does not jump).
    if (state.playing) state.settings.time += std::min(0.1f, std::chrono::duration<float>(start - lastIteration).count());
    lastIteration = start;
    for (const std::string& path : window.takeDroppedPaths()) loadSceneFile(state, path);
    window.setTitle("facet view: " + state.scene->source);
    window.syncImageSize(state.settings.width, state.settings.height, ImGui::IsAnyItemActive());
    int width = 0, height = 0;
    window.framebufferSize(width, height);
    if (width == 0 || height == 0) continue;  // minimized: nothing to draw into
    if (bench && framesLeft <= options.benchOrbit) orbitBenchStep(state, options.benchOrbit, static_cast<float>(height));

    // Start the Dear ImGui frame: the shortcuts and the panel edit state.settings
    const std::vector<KeyPress> presses = window.takePressedKeys();
    imgui.newFrame(presses);
    const ViewRequests keys = input.update(state, presses);
    if (keys.quit) glfwSetWindowShouldClose(window.handle(), GLFW_TRUE);
    if (keys.togglePanel) showPanel = !showPanel;
    PanelRequests panel;
    if (showPanel) {
      const FrameStats stats{renderer.rendererName(), drawTimes.median(), windowTimes.median(), state.scene->triangleCount(),
                             static_cast<int>(drawn.frame.lights.size()), drawn.frame.shadowLayerCount, drawn.version, drawn.error};
      panel = drawControlPanel(state, stats, reference, redrawEveryFrame);
      reference.drawImages(drawn.version);
    } else if (!drawn.error.empty()) {
      drawErrorOverlay(drawn.error);
    }

    // The 3D frame, when the scene or the settings changed (a batch screenshot
    // draws and times each of its frames). A value being typed waits until it
    // is done: "1200" would otherwise draw 1, 12 and 120 on the way.
    const bool typing = ImGui::GetIO().WantTextInput;
    changedLastFrame = !typing && drawChangedFrame(renderer, state, drawn, redrawEveryFrame || (batch && !bench && framesLeft > 0));
    if (changedLastFrame && drawn.error.empty()) drawTimes.add(drawn.milliseconds);
    if (batch && !drawn.error.empty()) throw Error(drawn.error);
    reference.update(drawn.version, [&] { return ReferenceRequest{drawn.version, drawn.scene, drawn.frame, drawn.image}; });
    reference.drawMainView(drawn.version);

    // Rendering: the 3D frame, then ImGui on top
    blitToWindow(gl, renderer, drawn, width, height);
    if ((keys.screenshot || panel.screenshot) && drawn.version > 0) saveScreenshot(state, drawn.image);
    imgui.render();

    if (bench) {
      glfwSwapBuffers(window.handle());
      if (framesLeft <= options.benchOrbit) benchFrames.push_back(millisecondsSince(start));
      if (--framesLeft > 0) continue;
      printOrbitReport(benchFrames, renderer.rendererName(), options.scenePath, state.settings);
      break;
    }
    // --screenshot: after `frames` frames (and the reference, when asked for), before the swap
    if (batch && --framesLeft <= 0 && (!options.followReference || reference.isFinal(drawn.version))) {
      const Image image = options.screenshotWithPanel ? readWindow(gl, width, height) : drawn.image;
      writePng(options.batchScreenshot, image);
      std::printf("screenshot written to %s: %dx%d, %d frames, GL frame %.1f ms (median)\n", options.batchScreenshot.c_str(), image.width(),
                  image.height(), options.frames, drawTimes.median());
      if (options.followReference) std::printf("%s\n", reference.summary().c_str());
      break;
    }
    glfwSwapBuffers(window.handle());
    windowTimes.add(millisecondsSince(start));
  }
  return 0;
}

}  // namespace facet::viewer
