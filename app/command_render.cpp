// facet render: one frame of a scene with the OpenGL backend, the CPU
// backend, the CPU backend's readable reference or the ray tracer, to a PNG.
#include <array>
#include <chrono>
#include <cstdio>
#include <memory>
#include <new>
#include <optional>
#include <string>

#include "command_line.h"
#include "cpu/pixel_probe.h"
#include "frame_setup.h"
#include "progress_bar.h"
#include "render_report.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "common/quote.h"
#include "common/stopwatch.h"
#include "compare/heat_map.h"
#include "compare/image_diff.h"
#include "cpu/cpu_renderer.h"
#include "cpu/reference/reference_renderer.h"
#include "image/png.h"
#include "pipeline/frame_inputs.h"
#include "ray/ray_renderer.h"
#include "render/stage.h"
#include "pipeline/bump_map.h"
#include "pipeline/displacement.h"
#include "scene/environment_map.h"
#include "scene/load_scene.h"
#include "pipeline/scene_additions.h"
#if FACET_HAVE_GL
#include "gl/gl_renderer.h"
#endif

namespace facet {
namespace {

struct RenderOptions {
  CommonOptions common;
  std::string backend = "gl";
  std::string context = "osmesa";
  int threads = 0;
  std::string stage = "image";  // render/stage.h: image, overdraw, depth, shadow-map, normals or light-N
  std::string shadowReport;     // a heat map of the frame against ray casting (renderer/PIPELINE.md, section 10)
  std::string probe;            // X,Y: explain that pixel (cpu/pixel_probe.h)
};

// The frame's settings as ray casting draws them to compare a rasterized frame with: primary and
// shadow rays only (ray.depth 1), one path through each pixel's centre, the builtin sphere as its triangles.
RenderSettings rayCastingOf(RenderSettings settings) {
  settings.ray.depth = 1;
  settings.ray.samples = 1;
  settings.ray.spheres = false;
  settings.camera.aperture = 0.0f;
  settings.antialiasing = AntialiasingSettings{};
  return settings;
}

std::unique_ptr<Renderer> makeRenderer(const RenderOptions& options, ProgressBar& progress) {
  return makeBackend(options.backend, options.context, options.threads, [&progress](double done) { progress.update(done); });
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand("render", "Render one frame of a scene to a PNG, headless, with the OpenGL or the CPU backend, or the ray tracer");
  addCommonOptions(*command, options->common, "the PNG to write (default: facet.png)");
  command->add_option("--backend", options->backend,
                      "gl (OpenGL, headless on llvmpipe), cpu (the CPU rasterizer), reference (the CPU rasterizer's one-triangle-at-a-time "
                      "reference: the same image, slowly) or ray (the ray tracer: shadow rays, reflection, refraction)")
      ->check(CLI::IsMember({"gl", "cpu", "reference", "ray"}));
  command->add_option("--context", options->context, "headless OpenGL context for --backend gl: osmesa or egl")
      ->check(CLI::IsMember({"osmesa", "egl"}));
  command->add_option("--threads", options->threads, "CPU backend and ray tracer threads (0: one per core)")->check(wholeNumberIn(0, 256));
  command->add_option("--output-stage", options->stage,
                      "what to write (renderer/PIPELINE.md, section 6, \"Stages\"): image (the frame); overdraw (the depth complexity: "
                      "fragments per pixel before the depth test, black 0, pale yellow the busiest pixel); depth (the z-buffer's window z, "
                      "near white to far dark grey); shadow-map (every shadow map side by side); normals (RGB = (N + 1)/2); light-N (the "
                      "frame lit by light N alone)");
  command->add_option("--probe", options->probe,
                      "X,Y: also explain that pixel (from the top left): the triangle kept there, its weights, P, N, V, each light's terms "
                      "and shadow test, by the CPU backend's functions, and the pixel this backend drew");
  command->add_option("--shadow-report", options->shadowReport,
                      "also ray cast the frame (ray.depth 1, the same settings) and write a heat map of where the image differs from it to "
                      "this PNG: where shadow maps are wrong (acne, peter-panning, aliasing), since rays cast exact shadows")
      ->check([](const std::string& path) { return path.empty() ? std::string("--shadow-report: an empty file name") : std::string(); });
  return [options]() {
    const auto start = std::chrono::steady_clock::now();
    const Stage stage = parseStage(options->stage);
    std::optional<std::array<int, 2>> probe;
    if (!options->probe.empty()) probe = parsePixel(options->probe, "--probe");
    const std::string output = options->common.output.empty() ? "facet.png" : options->common.output;  // -o "" never parses
    // Before loading and rendering (minutes at large sizes): a frame nobody can write is not drawn.
    checkOutputFile(output, {options->common.scenePath, options->common.settingsPath});
    if (!options->shadowReport.empty()) {
      if (options->backend == "ray") throw UsageError("--shadow-report compares a rasterizer with ray casting: use it with --backend gl, cpu or reference");
      if (stage.kind != StageKind::Image) throw UsageError("--shadow-report compares images: use it with --output-stage image");
      checkOutputFile(options->shadowReport, {options->common.scenePath, options->common.settingsPath, output});
    }
    Scene scene = loadScene(options->common.scenePath);
    const RenderSettings asked = settingsFor(options->common, scene);
    const PreparedFrame prepared = prepareFrame(scene, asked, options->threads);
    const RenderSettings& settings = prepared.settings;
    const SceneAdditions& added = prepared.added;
    const FrameInputs& frame = prepared.frame;
    for (const std::string& warning : scene.warnings) std::fprintf(stderr, "warning: %s: %s\n", scene.source.c_str(), warning.c_str());
    for (const std::string& warning : frame.warnings) std::fprintf(stderr, "warning: %s: %s\n", scene.source.c_str(), warning.c_str());
#if FACET_HAVE_GL
    if (options->backend == "gl") refuseCpuOnlyFrame(frame);  // before the driver is loaded
#endif
    checkStage(frame, stage);
    if (probe && ((*probe)[0] >= frame.width || (*probe)[1] >= frame.height))
      throw UsageError("--probe " + options->probe + ": outside the " + std::to_string(frame.width) + "x" + std::to_string(frame.height) + " frame");
    ProgressBar progress("ray tracing");  // drawn on a terminal only
    // Where the time to the first PNG goes besides the passes: reading the scene, the renderer's start-up (GL: the context), the PNG.
    const double loading = millisecondsSince(start);
    const auto startup = std::chrono::steady_clock::now();
    std::unique_ptr<Renderer> renderer = makeRenderer(*options, progress);
    const double startingUp = millisecondsSince(startup);
    RenderResult result;
    try {
      result = renderStage(*renderer, scene, frame, stage);
    } catch (const OutOfMemory&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw OutOfMemory("rendering " + scene.source + " (" + std::to_string(frame.width) + "x" + std::to_string(frame.height) + ")");
    }
    progress.finish();  // the bar's line cleared before the report
    std::optional<DiffResult> shadowDiff;
    if (!options->shadowReport.empty()) {
      const FrameInputs cast = buildFrameInputs(scene, rayCastingOf(settings));
      const Image rays = makeRayRenderer(options->threads)->render(scene, cast).image;
      // One level is rounding (the same attributes, rounded differently); more is the shadow map.
      DiffThresholds overOneLevel;
      overOneLevel.failThreshold = 1.0 / 255.0;
      shadowDiff = compareImages(rays, result.image, overOneLevel);
      writePng(options->shadowReport, heatMap(rays, result.image, overOneLevel));
    }
    const auto writing = std::chrono::steady_clock::now();
    writePng(output, result.image);
    const double written = millisecondsSince(writing);
    const double total = millisecondsSince(start);

    std::printf("rendered %s: %s, %dx%d, %s shading, %s, shadows %s\n", scene.source.c_str(), countOf(scene.triangleCount(), "triangle").c_str(),
                frame.width, frame.height, std::string(kShadingModeNames[static_cast<std::size_t>(frame.shading)]).c_str(),
                countOf(frame.lights.size(), "light").c_str(), frame.shadowLayerCount > 0 ? "on" : "off");
    if (added.particles) std::printf("particles: %s at time %g s\n", countOf(added.particles, "sprite").c_str(), static_cast<double>(settings.time));
    if (added.splats) std::printf("volume: %s (splatting)\n", countOf(added.splats, "splat").c_str());
    if (added.isosurface)
      std::printf("volume: %s (marching cubes)\n", countOf(added.isoTriangles, "iso-surface triangle").c_str());
    std::printf("backend: %s\n", renderer->description().c_str());
    std::printf("  %-28s %9.2f ms\n", kSceneInputsLine, loading);
    std::printf("  %-28s %9.2f ms\n", options->backend == "gl" ? kGlStartupLine : kRendererStartupLine, startingUp);
    for (const PassTiming& t : result.timings) std::printf("  %-28s %9.2f ms\n", t.pass.c_str(), t.milliseconds);
    std::printf("  %-28s %9.2f ms\n", kPngWriteLine, written);
    for (const std::string& note : result.notes) std::printf("%s\n", note.c_str());
    if (shadowDiff)
      std::printf("shadow report: %lld pixels differ from ray casting, %lld by more than 1 level, at most %d; heat map written to %s\n",
                  static_cast<long long>(shadowDiff->differingPixels), static_cast<long long>(shadowDiff->failingPixels), shadowDiff->maxDifference,
                  options->shadowReport.c_str());
    std::printf("  %-28s %9.2f ms\n", kCommandTotalLine, total);
    std::printf("image written to %s\n", output.c_str());
    if (probe) {
      const int x = (*probe)[0], y = frame.height - 1 - (*probe)[1];
      if (stage.kind == StageKind::Image) {
        const Rgba8 drawn = result.image.at(x, y);
        std::printf("probe: %s drew %d %d %d\n", options->backend.c_str(), drawn.r, drawn.g, drawn.b);
      }
      for (const std::string& line : describeProbe(probePixel(scene, frame, x, y))) std::printf("probe: %s\n", line.c_str());
    }
    return 0;
  };
}

}  // namespace facet
