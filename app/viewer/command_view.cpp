// facet view: the scene in a window, drawn by the OpenGL backend, with a
// panel for every setting, an orbit camera, and the CPU reference beside it.
#include <cstdio>
#include <memory>

#include "command_line.h"
#include "commands.h"
#include "common/error.h"
#include "render/stage.h"
#include "scene/load_scene.h"
#include "viewer/viewer_loop.h"
#include "vocabulary/limits.h"

namespace facet {
namespace {

struct ViewCommandOptions {
  CommonOptions common;
  std::string screenshot;
  int frames = 3;
  bool withPanel = false;
  bool reference = false;
  bool rayReference = false;
  int benchOrbit = 0;
  std::string backend = "auto";
  int dragPreview = 2;
  bool noPanel = false;
  std::string pick;
  std::vector<std::string> drops;
  std::string tab;
  std::string stage;
  std::string stageSource = "gl";
  bool compareStages = false;
};

}  // namespace

Command addViewCommand(CLI::App& app) {
  auto options = std::make_shared<ViewCommandOptions>();
  CLI::App* command = app.add_subcommand("view", std::string(kViewSummary));
  addCommonOptions(*command, options->common, "where F12 and Ctrl+S write screenshots (default: facet-view-N.png, the first N not taken)");
  CLI::Option* screenshot = command->add_option(
      "--screenshot", options->screenshot, "draw --frames frames, write the 3D view (without the panel) to this PNG, and exit");
  command->add_option("--frames", options->frames, "how many frames --screenshot draws first")->check(CLI::Range(1, kMaxViewerFrames))->needs(screenshot);
  command->add_flag("--with-panel", options->withPanel, "--screenshot writes the whole window, panel included")->needs(screenshot);
  command->add_flag("--reference", options->reference,
                    "render the CPU reference after every change; --screenshot waits for it and prints its figures");
  command->add_flag("--ray-reference", options->rayReference,
                    "the reference is the ray tracer (shadow rays, reflections, refraction), not the CPU rasterizer");
  command->add_option("--backend", options->backend,
                      "what draws the 3D view: gl (OpenGL on the window's context), cpu (the CPU rasterizer, the same bytes), or auto: cpu where "
                      "OpenGL is a software rasterizer (llvmpipe), else gl")
      ->check(CLI::IsMember({"auto", "gl", "cpu"}));
  command->add_option("--pick", options->pick,
                      "X,Y: pick that pixel of the 3D view (from the top left) once the first frame is drawn, as a click does; --screenshot "
                      "also prints what both backends say of it");
  command->add_option("--drop", options->drops,
                      "open FILE as if dropped on the window once the first frame is drawn: a .json settings file, else a scene (repeatable; for "
                      "scripted runs)");
  command->add_option("--tab", options->tab, "the panel's tab shown first")
      ->check(CLI::IsMember({"settings", "files", "reference", "pixel", "matrices", "stages", "help"}));
  command->add_option("--stage", options->stage,
                      "show a stage over the 3D view, as render --output-stage names it: image, overdraw, depth, shadow-map, normals, light-N");
  command->add_option("--stage-source", options->stageSource, "the stage from gl, cpu, or the heat map of their difference")
      ->check(CLI::IsMember({"gl", "cpu", "difference"}));
  command->add_flag("--compare-stages", options->compareStages,
                    "--screenshot also draws every stage of the frame with both backends and prints how many pixels differ in each");
  command->add_flag("--no-panel", options->noPanel, "start with the panel hidden (H shows it): the 3D view takes the whole window");
  command->add_option("--drag-preview", options->dragPreview,
                      "while a drag or the wheel moves the camera, draw frames at 1/N of each side (the full frame follows when it stops); 1: always full")
      ->check(CLI::Range(1, viewer::kMaxDragPreview))
      ->capture_default_str();
  command->add_option("--bench-orbit", options->benchOrbit,
                      "orbit the camera once around the scene in N frames, as a drag would, print the median and spread of ms per window frame "
                      "and the ratio to a headless `facet render` frame of the same scene and size, and exit")
      ->check(CLI::Range(1, kMaxViewerFrames))
      ->excludes(screenshot);
  return [options]() {
    viewer::ViewerOptions view;
    view.scene = std::make_shared<const Scene>(loadScene(options->common.scenePath));
    for (const std::string& warning : view.scene->warnings) std::fprintf(stderr, "warning: %s: %s\n", view.scene->source.c_str(), warning.c_str());
    view.scenePath = options->common.scenePath;
    view.settings = settingsFor(options->common, *view.scene);
    view.settingsPath = options->common.settingsPath;
    view.screenshotPath = options->common.output;
    view.batchScreenshot = options->screenshot;
    view.frames = options->frames;
    view.screenshotWithPanel = options->withPanel;
    view.followReference = options->reference;
    view.rayReference = options->rayReference;
    view.benchOrbit = options->benchOrbit;
    view.dragPreview = options->dragPreview;
    view.showPanel = !options->noPanel;
    view.drops = options->drops;
    view.tab = options->tab;
    view.stage = options->stage;
    view.stageSource = options->stageSource == "cpu" ? viewer::StageSource::Cpu
                       : options->stageSource == "difference" ? viewer::StageSource::Difference : viewer::StageSource::OpenGl;
    view.compareStages = options->compareStages;
    if (!view.stage.empty()) {  // a name it does not read is a usage error before the window opens, naming this command's option
      try {
        parseStage(view.stage);
      } catch (const UsageError& e) {
        const std::string message = e.what(), asked = "--output-stage";
        throw UsageError(message.rfind(asked, 0) == 0 ? "--stage" + message.substr(asked.size()) : message);
      }
    }
    if (!options->pick.empty()) view.pick = parsePixel(options->pick, "--pick");
    view.backend = options->backend == "gl" ? viewer::FrameBackend::OpenGl : options->backend == "cpu" ? viewer::FrameBackend::Cpu : viewer::FrameBackend::Auto;
    return viewer::runViewer(view);
  };
}

}  // namespace facet
