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
#include <utility>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/stopwatch.h"
#include "gl/gl_renderer.h"
#include "image/png.h"
#include "pipeline/frame_inputs.h"
#include "settings/settings_json.h"
#include "viewer/control_panel.h"
#include "viewer/frame_times.h"
#include "viewer/imgui_session.h"
#include "viewer/orbit_bench.h"
#include "viewer/pixel_pick.h"
#include "viewer/reference_view.h"
#include "viewer/stage_view.h"
#include "viewer/view_frame.h"
#include "viewer/view_input.h"
#include "gl/gl_functions.h"
#include "viewer/viewer_state.h"
#include "viewer/viewer_window.h"

namespace facet::viewer {
namespace {

using Clock = std::chrono::steady_clock;

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

// The panel's first width, in ImGui's units (the window's pixels where the
// display does not scale): "parallelWidth" and a drag box fit side by side.
constexpr float kPanelWidth = 360.0f;

// The CPU reference leaves a core to the window (and llvmpipe).
int referenceThreads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency()) - 1); }

// The window's back buffer, panel included: read before the swap, since
// the front buffer reads back as zeros under Xvfb. Opaque, as the GL image is.
Image readWindow(const gl::GlFunctions& gl, int width, int height) {
  Image image(width, height);
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.PixelStorei(GL_PACK_ROW_LENGTH, 0);
  gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.at(x, y).a = 255;
  return image;
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
  bool showPanel = options.showPanel;
  float panelWidth = kPanelWidth;  // as the user last left it (ImGui units)
  ViewerWindow window(state.settings.width, state.settings.height, showPanel ? static_cast<int>(panelWidth) : 0);
  glfwSwapInterval(batch ? 0 : 1);
  if (!batch) window.setMinimumSize(kMinimumWindowWidth, kMinimumWindowHeight);
  const gl::GlFunctions windowGl = gl::loadGlFunctions(glfwGetProcAddress);  // the window context's functions
  const std::unique_ptr<WindowGlRenderer> rendererOwner = makeWindowGlRenderer(glfwGetProcAddress);
  WindowGlRenderer& renderer = *rendererOwner;
  ImGuiSession imgui(window.handle());
  ReferenceView reference(windowGl, referenceThreads(), options.followReference, options.rayReference);
  ViewFrame view(windowGl, renderer, 0);
  ViewInput input;
  PixelPick pick(windowGl);
  MatrixSelection matrices;
  StageView stages(windowGl);
  if (!options.stage.empty()) stages.choose(options.stage, options.stageSource);
  std::vector<std::string> scriptedDrops = options.drops;
  std::optional<std::array<int, 2>> pickAsked = options.pick;
  state.backend = options.backend;
  state.dragPreview = options.dragPreview;
  state.openTab = options.tab;

  FrameTimes drawTimes, windowTimes;
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
    for (const std::string& path : window.takeDroppedPaths()) openDroppedFile(state, path);
    if (view.drawn().version > 0)  // --drop: as if dropped once the first frame is on screen
      for (const std::string& path : std::exchange(scriptedDrops, {})) openDroppedFile(state, path);
    window.setTitle("facet view: " + state.scene->source);
    // The panel's side of the window, in framebuffer pixels; the image takes the rest.
    const float pixelsPerUnit = ImGui::GetIO().DisplayFramebufferScale.x > 0 ? ImGui::GetIO().DisplayFramebufferScale.x : 1.0f;
    const int besideWidth = showPanel ? static_cast<int>(panelWidth * pixelsPerUnit + 0.5f) : 0;
    window.syncImageSize(state.settings.width, state.settings.height, besideWidth, ImGui::IsAnyItemActive());
    int width = 0, height = 0;
    window.framebufferSize(width, height);
    if (width == 0 || height == 0) continue;  // minimized: nothing to draw into
    const ViewRect viewRect{std::min(besideWidth, width - 1), 0, std::max(1, width - besideWidth), height};
    if (bench && framesLeft <= options.benchOrbit) orbitBenchStep(state, options.benchOrbit, static_cast<float>(height));

    // Start the Dear ImGui frame: the shortcuts and the panel edit state.settings
    const std::vector<KeyPress> presses = window.takePressedKeys();
    imgui.newFrame(presses);
    const ViewRequests keys = input.update(state, presses, static_cast<float>(viewRect.x) / pixelsPerUnit);
    if (keys.quit) glfwSetWindowShouldClose(window.handle(), GLFW_TRUE);
    if (keys.togglePanel) showPanel = !showPanel;
    PanelRequests panel;
    if (showPanel) {
      const DrawnFrame& drawn = view.drawn();
      const FrameStats stats{renderer.rendererName(), view.backendLine(state.backend), drawTimes.median(), windowTimes.median(),
                             state.scene->triangleCount(), static_cast<int>(drawn.frame.lights.size()), drawn.frame.shadowLayerCount,
                             drawn.version, drawn.error};
      panel = drawControlPanel(state, stats, reference, pick, view, stages, matrices, redrawEveryFrame, panelWidth);
      reference.drawImages(drawn.version);
    } else if (!view.drawn().error.empty()) {
      drawErrorOverlay(view.drawn().error);
    }

    // The 3D frame, when the scene or the settings changed (a batch screenshot
    // draws and times each of its frames). A value being typed waits until it
    // is done: "1200" would otherwise draw 1, 12 and 120 on the way. While a
    // drag moves the camera the frame is a preview at reduced size; the
    // first frame without a move draws it whole.
    const bool typing = ImGui::GetIO().WantTextInput;
    const bool preview = keys.cameraMoved || (bench && framesLeft <= options.benchOrbit);
    changedLastFrame = !typing && view.drawIfChanged(state, preview, redrawEveryFrame || (batch && !bench && framesLeft > 0));
    const DrawnFrame& drawn = view.drawn();
    if (changedLastFrame && drawn.error.empty()) drawTimes.add(drawn.milliseconds);
    if (batch && !drawn.error.empty()) throw Error(drawn.error);
    // The reference compares whole frames, not previews.
    if (!drawn.preview)
      reference.update(drawn.version, [&] { return ReferenceRequest{drawn.version, drawn.scene, drawn.frame, view.glImage()}; });
    const float unitsPerPixel = 1.0f / pixelsPerUnit;
    // A click on the view picks the pixel under it in the frame on screen (a whole one: a click moves no camera).
    if (keys.picked && drawn.version > 0 && !drawn.preview) {
      const float fromLeft = (keys.pickX * pixelsPerUnit - static_cast<float>(viewRect.x)) / static_cast<float>(viewRect.width);
      const float fromTop = keys.pickY * pixelsPerUnit / static_cast<float>(viewRect.height);
      pickAsked = {static_cast<int>(fromLeft * static_cast<float>(drawn.frame.width)), static_cast<int>(fromTop * static_cast<float>(drawn.frame.height))};
    }
    if (pickAsked && drawn.version > 0 && !drawn.preview) {
      const int x = std::clamp((*pickAsked)[0], 0, drawn.frame.width - 1), fromTop = std::clamp((*pickAsked)[1], 0, drawn.frame.height - 1);
      pick.pick(view, x, drawn.frame.height - 1 - fromTop);
      pickAsked.reset();
    }
    stages.update(view);
    stages.drawMainView(ImVec2(static_cast<float>(viewRect.x) * unitsPerPixel, 0.0f), ImGui::GetIO().DisplaySize);
    pick.drawCoverage(drawn.version, ImVec2(static_cast<float>(viewRect.x) * unitsPerPixel, 0.0f), ImGui::GetIO().DisplaySize);
    pick.drawMarker(drawn.version, ImVec2(static_cast<float>(viewRect.x) * unitsPerPixel, 0.0f), ImGui::GetIO().DisplaySize);
    reference.drawMainView(drawn.version, ImVec2(static_cast<float>(viewRect.x) * unitsPerPixel, 0.0f), ImGui::GetIO().DisplaySize);

    // Rendering: the 3D frame, then ImGui on top
    view.blit(width, height, viewRect);
    if ((keys.screenshot || panel.screenshot) && drawn.version > 0) saveScreenshot(state, drawn.image);
    imgui.render();

    if (bench) {
      glfwSwapBuffers(window.handle());
      if (framesLeft <= options.benchOrbit) benchFrames.push_back(millisecondsSince(start));
      if (--framesLeft > 0) continue;
      printOrbitReport(benchFrames, view.backendLine(state.backend), state.dragPreview, options.scenePath, state.settings);
      break;
    }
    // --screenshot: after `frames` frames (and the reference, when asked for), before the swap
    if (batch && --framesLeft <= 0 && (!options.followReference || reference.isFinal(drawn.version))) {
      // The 3D view: the frame, or the stage shown over it.
      const Image image = options.screenshotWithPanel ? readWindow(windowGl, width, height) : stages.shownImage().empty() ? drawn.image : stages.shownImage();
      writePng(options.batchScreenshot, image);
      std::printf("screenshot written to %s: %dx%d, %d frames, %s, frame %.1f ms (median)\n", options.batchScreenshot.c_str(), image.width(),
                  image.height(), options.frames, view.backendLine(state.backend).c_str(), drawTimes.median());
      if (options.followReference) std::printf("%s\n", reference.summary().c_str());
      if (options.pick) pick.print();
      if (options.compareStages) {
        stages.compareAll(view);
        for (const std::string& line : stages.comparisonLines()) std::printf("%s\n", line.c_str());
      }
      break;
    }
    glfwSwapBuffers(window.handle());
    windowTimes.add(millisecondsSince(start));
  }
  return 0;
}

}  // namespace facet::viewer
