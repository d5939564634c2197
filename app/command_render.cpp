// facet render: one frame of a scene with the OpenGL backend, the CPU
// backend, the CPU backend's readable reference or the ray tracer, to a PNG;
// or, with --turntable N, N frames around the scene to N PNGs.
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <new>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "command_line.h"
#include "output_template.h"
#include "sample_summary.h"
#include "cpu/pixel_probe.h"
#include "frame_setup.h"
#include "progress_bar.h"
#include "render_report.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "settings/settings_files.h"
#include "common/quote.h"
#include "common/stopwatch.h"
#include "compare/heat_map.h"
#include "compare/image_diff.h"
#include "cpu/cpu_renderer.h"
#include "cpu/reference/reference_renderer.h"
#include "image/png.h"
#include "pipeline/camera_orbit.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/frame_spine.h"
#include "ray/ray_renderer.h"
#include "render/stage.h"
#include "scene/load_scene.h"
#include "vocabulary/limits.h"
#if FACET_HAVE_GL
#include "gl/gl_renderer.h"
#endif

namespace facet {
namespace {

struct RenderOptions {
  CommonOptions common;
  std::string backend = "gl";
  std::string context = "auto";
  int threads = 0;
  std::string stage = "image";  // render/stage.h: image, overdraw, depth, shadow-map, normals or light-N
  std::string shadowReport;     // a heat map of the frame against ray casting (renderer/PIPELINE.md, "Ray tracing")
  std::string probe;            // X,Y: explain that pixel (cpu/pixel_probe.h)
  int turntable = 1;            // frames around the scene, 360/N degrees of azimuth apart
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

// The file names of `frames` frames from an -o (or --shadow-report) template.
// More than one frame needs {frame} or {n} in it: one name would be
// overwritten by every frame.
std::vector<std::string> frameNames(const std::string& pattern, const std::string& option, const TemplateValues& values, int frames) {
  const OutputTemplate names(pattern, option);
  if (frames > 1 && !names.numbersFrames())
    throw UsageError("--turntable " + std::to_string(frames) + ": " + option + " " + quotedPath(pattern) +
                     " has no {frame} or {n}, so every frame would get that one name (e.g. turntable_{frame}.png)");
  std::vector<std::string> files;
  for (int k = 0; k < frames; ++k) files.push_back(names.expand(values, k, frames));
  return files;
}

std::unique_ptr<Renderer> makeRenderer(const RenderOptions& options, RenderProgress progress) {
  return makeBackend(options.backend, options.context, options.threads, std::move(progress));
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand("render", "Render one frame of a scene to a PNG (--turntable: N frames around it), headless, with the OpenGL or the CPU backend, or the ray tracer");
  addCommonOptions(*command, options->common,
                   "the PNG to write (default: facet.png, with --turntable facet_{frame}.png); a template, as F3D's --output: {scene} (the file's name without extension, or "
                   "the builtin's), {backend}, {frame} or {n} (the frame from 0, padded to the digits of the last), {frame:W} (W digits), "
                   "{{ and }} for braces");
  command->add_option("--backend", options->backend,
                      "gl (OpenGL, headless on llvmpipe), auto (gl when a driver loads, cpu otherwise), cpu (the CPU rasterizer), reference (the CPU rasterizer's one-triangle-at-a-time "
                      "reference: the same image, slowly) or ray (the ray tracer: shadow rays, reflection, refraction)")
      ->check(CLI::IsMember({"gl", "auto", "cpu", "reference", "ray"}));
  command->add_option("--context", options->context,
                      "headless OpenGL context for --backend gl: auto (EGL surfaceless, OSMesa where EGL cannot start), egl or osmesa")
      ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  command->add_option("--threads", options->threads, "CPU backend and ray tracer threads (0: one per core)")->check(wholeNumberIn(0, kMaxThreads));
  command->add_option("--output-stage", options->stage,
                      "what to write (renderer/PIPELINE.md, \"Stages\"): image (the frame); overdraw (the depth complexity: "
                      "fragments per pixel before the depth test, black 0, pale yellow the busiest pixel); depth (the z-buffer's window z, "
                      "near white to far dark grey); shadow-map (every shadow map side by side); normals (RGB = (N + 1)/2); light-N (the "
                      "frame lit by light N alone)");
  command->add_option("--turntable", options->turntable,
                      "render N frames around the scene: frame k turns the camera 360k/N degrees of azimuth about camera.up through "
                      "camera.reference (after any --camera-* move), with one scene and one renderer; an -o must hold {frame} or {n}")
      ->check(wholeNumberIn(1, 3600));
  command->add_option("--probe", options->probe,
                      "X,Y: also explain that pixel (from the top left): the triangle kept there, its weights, P, N, V, each light's terms "
                      "and shadow test, by the CPU backend's functions, and the pixel this backend drew");
  command->add_option("--shadow-report", options->shadowReport,
                      "also ray cast the frame (ray.depth 1, the same settings) and write a heat map of where the image differs from it to "
                      "this PNG (a template, as -o: one per --turntable frame): where shadow maps are wrong (acne, peter-panning, aliasing), since rays cast exact shadows")
      ->check([](const std::string& path) { return path.empty() ? std::string("--shadow-report: an empty file name") : std::string(); });
  return [options]() {
    const auto start = std::chrono::steady_clock::now();
    const Stage stage = parseStage(options->stage);
    std::optional<std::array<int, 2>> probe;
    if (!options->probe.empty()) probe = parsePixel(options->probe, "--probe");
    const int frames = options->turntable;
    if (probe && frames > 1)
      throw UsageError("--probe explains one frame's pixel: use it without --turntable (turn that frame's camera with --camera-azimuth)");
    const TemplateValues names{sceneNameOf(options->common.scenePath), options->backend};
    const std::vector<std::string> outputs =
        frameNames(!options->common.output.empty() ? options->common.output : frames > 1 ? "facet_{frame}.png" : "facet.png", "-o", names,
                   frames);  // -o "" never parses
    // Before loading and rendering (minutes at large sizes): a frame nobody can write is not drawn.
    const std::vector<std::string> inputs{options->common.scenePath, options->common.settingsPath};
    for (const std::string& output : outputs) checkOutputFile(output, inputs);
    std::vector<std::string> reports;
    std::vector<NamedOutput> toWrite;
    for (const std::string& output : outputs) toWrite.push_back({output, "-o"});
    if (!options->shadowReport.empty()) {
      if (options->backend == "ray") throw UsageError("--shadow-report compares a rasterizer with ray casting: use it with --backend gl, cpu or reference");
      if (stage.kind != StageKind::Image) throw UsageError("--shadow-report compares images: use it with --output-stage image");
      reports = frameNames(options->shadowReport, "--shadow-report", names, frames);
      for (const std::string& report : reports) checkOutputFile(report, inputs);
      for (const std::string& report : reports) toWrite.push_back({report, "--shadow-report"});
    }
    checkDistinctOutputs(toWrite);
    const auto loaded = std::make_shared<const Scene>(loadScene(options->common.scenePath));
    // The camera moves are the spine's, made after the volume's box joins the
    // scene: the auto camera frames it, and sprites face the moved camera.
    CommonOptions unmoved = options->common;
    unmoved.orbit = CameraOrbit{};
    const RenderSettings asked = settingsFor(unmoved, *loaded);
    // Before drawing: no output is a file the scene was read from (its
    // buffers, images) or one the settings name (maps, volume, sprites).
    std::vector<std::string> read = loaded->files;
    for (const std::string& file : namedFiles(asked)) read.push_back(file);
    // Each file's identity once: a turntable has thousands of outputs.
    std::set<std::string> readKeys;
    for (const std::string& file : read) readKeys.insert(fileIdentityKey(file));
    for (const NamedOutput& output : toWrite)
      if (readKeys.count(fileIdentityKey(output.path))) throw Error(sameFileAsInput(output.path, read));
    FrameSpine spine(loaded, options->threads);
    // Frame k of a turntable: the asked move, turned a further k/N of a circle about camera.up.
    const auto orbitOf = [&](int k) {
      CameraOrbit orbit = options->common.orbit;
      orbit.azimuthDeg += 360.0 * k / frames;
      return orbit;
    };
    std::set<std::string> warned;  // a turntable's frames warn of the same things once
    const auto prepare = [&](int k) {
      PreparedFrame prepared = spine.frame(asked, orbitOf(k));
      for (const std::string& warning : prepared.warnings)
        if (warned.insert(warning).second) std::fprintf(stderr, "warning: %s: %s\n", prepared.scene->source.c_str(), warning.c_str());
      checkStage(prepared.inputs, stage);
      return prepared;
    };
    PreparedFrame frame = prepare(0);
#if FACET_HAVE_GL
    if (options->backend == "auto") {
      try {
        refuseCpuOnlyFrame(frame.inputs);
      } catch (const Error&) {
        options->backend = "cpu";  // a frame only the CPU rasterizer draws
      }
    }
#endif
    // Before the backend starts (GL: its driver): settings the backend named
    // on the command line cannot draw are a command line that does not work.
    if (stage.kind == StageKind::Image) {
      try {
        refuseUndrawnImage(options->backend, frame.inputs);
      } catch (const Error& e) {
        throw UsageError(e.what());
      }
    }
    if (probe && ((*probe)[0] >= frame.inputs.width || (*probe)[1] >= frame.inputs.height))
      throw UsageError("--probe " + options->probe + ": outside the " + std::to_string(frame.inputs.width) + "x" + std::to_string(frame.inputs.height) +
                       " frame");
    ProgressBar progress(frames > 1 ? "ray tracing " + std::to_string(frames) + " frames" : "ray tracing");  // drawn on a terminal only
    int frameIndex = 0;
    // Where the time to the first PNG goes besides the passes: reading the scene, the renderer's start-up (GL: the context), the PNG.
    const double loading = millisecondsSince(start);
    const auto startup = std::chrono::steady_clock::now();
    // One renderer (GL: one context) draws every frame.
    std::unique_ptr<Renderer> renderer =
        makeRenderer(*options, [&progress, &frameIndex, frames](double done) { progress.update((frameIndex + done) / frames); });
    const double startingUp = millisecondsSince(startup);
    const FrameInputs first = frame.inputs;  // the report's figures
    const SceneAdditions added = frame.added;
    RenderResult result;
    std::vector<double> frameTimes;
    std::vector<std::optional<DiffResult>> shadowDiffs;
    double written = 0;
    for (frameIndex = 0; frameIndex < frames; ++frameIndex) {
      if (frameIndex > 0) frame = prepare(frameIndex);
      const Scene& scene = *frame.scene;
      const auto drawing = std::chrono::steady_clock::now();
      try {
        result = renderStage(*renderer, scene, frame.inputs, stage);
      } catch (const OutOfMemory&) {
        throw;
      } catch (const std::bad_alloc&) {
        throw OutOfMemory("rendering " + scene.source + " (" + std::to_string(frame.inputs.width) + "x" + std::to_string(frame.inputs.height) + ")");
      }
      std::optional<DiffResult> shadowDiff;
      if (!reports.empty()) {
        const FrameInputs cast = buildFrameInputs(scene, rayCastingOf(frame.settings));
        const Image rays = makeRayRenderer(options->threads)->render(scene, cast).image;
        // One level is rounding (the same attributes, rounded differently); more is the shadow map.
        DiffThresholds overOneLevel;
        overOneLevel.failThreshold = 1.0 / 255.0;
        shadowDiff = compareImages(rays, result.image, overOneLevel);
        writePng(reports[static_cast<std::size_t>(frameIndex)], heatMap(rays, result.image, overOneLevel));
      }
      shadowDiffs.push_back(shadowDiff);
      const auto writing = std::chrono::steady_clock::now();
      writePng(outputs[static_cast<std::size_t>(frameIndex)], result.image);
      written = millisecondsSince(writing);
      frameTimes.push_back(millisecondsSince(drawing));
    }
    progress.finish();  // the bar's line cleared before the report
    const double total = millisecondsSince(start);

    const Scene& scene = *frame.scene;
    std::printf("rendered %s: %s, %dx%d, %s shading, %s, shadows %s; %s\n", scene.source.c_str(), countOf(scene.triangleCount(), "triangle").c_str(),
                first.width, first.height, std::string(kShadingModeNames[static_cast<std::size_t>(first.shading)]).c_str(),
                countOf(first.lights.size(), "light").c_str(), first.shadowLayerCount > 0 ? "on" : "off", renderer->description().c_str());
    if (added.particles) std::printf("particles: %s at time %g s\n", countOf(added.particles, "sprite").c_str(), static_cast<double>(asked.time));
    if (added.splats) std::printf("volume: %s (splatting)\n", countOf(added.splats, "splat").c_str());
    if (added.isosurface)
      std::printf("volume: %s (marching cubes)\n", countOf(added.isoTriangles, "iso-surface triangle").c_str());
    std::printf("backend: %s\n", renderer->description().c_str());
    std::printf("  %-28s %9.2f ms\n", kSceneInputsLine, loading);
    std::printf("  %-28s %9.2f ms\n", renderer->description().starts_with("gl:") ? kGlStartupLine : kRendererStartupLine, startingUp);
    const auto printShadowReport = [](const DiffResult& diff, const std::string& path) {
      std::printf("shadow report: %lld pixels differ from ray casting, %lld by more than 1 level, at most %d; heat map written to %s\n",
                  static_cast<long long>(diff.differingPixels), static_cast<long long>(diff.failingPixels), diff.maxDifference, path.c_str());
    };
    if (frames == 1) {
      for (const PassTiming& t : result.timings) std::printf("  %-28s %9.2f ms\n", t.pass.c_str(), t.milliseconds);
      std::printf("  %-28s %9.2f ms\n", kPngWriteLine, written);
      for (const std::string& note : result.notes) std::printf("%s\n", note.c_str());
      if (shadowDiffs[0]) printShadowReport(*shadowDiffs[0], reports[0]);
      std::printf("  %-28s %9.2f ms\n", kCommandTotalLine, total);
      std::printf("image written to %s\n", outputs[0].c_str());
    } else {
      std::printf("turntable: %d frames, %g degrees apart about camera.up through camera.reference (render and PNG write each)\n", frames,
                  360.0 / frames);
      for (int k = 0; k < frames; ++k) {
        const auto at = static_cast<std::size_t>(k);
        std::printf("  frame %-*d azimuth %8.3f %9.2f ms  %s\n", static_cast<int>(std::to_string(frames - 1).size()), k,
                    orbitOf(k).azimuthDeg, frameTimes[at], outputs[at].c_str());
        if (shadowDiffs[at]) printShadowReport(*shadowDiffs[at], reports[at]);
      }
      double frameTotal = 0;
      for (const double t : frameTimes) frameTotal += t;
      std::printf("  %-28s %9.2f ms, median %.2f ms a frame\n", "frames", frameTotal, summarize(frameTimes).median);
      std::printf("  %-28s %9.2f ms\n", kCommandTotalLine, total);
      std::printf("%d images written, %s to %s\n", frames, outputs.front().c_str(), outputs.back().c_str());
    }
    if (probe) {
      const int x = (*probe)[0], y = frame.inputs.height - 1 - (*probe)[1];
      if (stage.kind == StageKind::Image) {
        const Rgba8 drawn = result.image.at(x, y);
        std::printf("probe: %s drew %d %d %d\n", options->backend.c_str(), drawn.r, drawn.g, drawn.b);
      }
      for (const std::string& line : describeProbe(probePixel(scene, frame.inputs, x, y))) std::printf("probe: %s\n", line.c_str());
    }
    return 0;
  };
}

}  // namespace facet
