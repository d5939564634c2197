// facet bench: the CPU reference rasterizer and OpenGL on llvmpipe, side by
// side, on the same scenes at the same thread count.
//
// Index of this file
//   [SECTION] Figures of the stages the settings add
//   [SECTION] The command
//
// In one process, for each scene, every backend renders `--warmup` frames,
// then `--frames` frames alternately (cpu, gl, lean, cpu, gl, lean, ...) so
// background load hits them alike; a frame is one Renderer::render call (GL:
// scene upload, both passes and the read-back of the image), after the
// backend has forgotten any shadow maps it kept (unless --keep-shadow-maps).
// `lean` is llvmpipe with the plainest programs that draw the same picture
// (bench_lean_gl.h), a floor for what the gl column's contract costs. Peak
// memory is that of a child process (this executable, `bench --child ...`)
// that builds one scene and renders it with one backend, so each backend's
// figure is its own: wait4's ru_maxrss, measured for every scene before this
// process builds any (bench_memory.h). `--callgrind` renders one scene with
// one backend with callgrind's instrumentation switched on around the frames
// only. `--sweep` (bench_sweep.h) grows triangles, pixels and lights instead.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#define CALLGRIND_ZERO_STATS
#endif

#include "bench_memory.h"
#include "bench_scenes.h"
#include "bench_sweep.h"
#include "child_process.h"
#include "command_line.h"
#include "bench_rays.h"
#include "commands.h"
#include "sample_summary.h"
#include "common/error.h"
#include "common/stopwatch.h"
#include "compare/image_diff.h"
#include "cpu/cpu_renderer.h"
#include "ray/ray_renderer.h"
#include "image/png.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/frame_spine.h"
#include "vocabulary/limits.h"
#if FACET_HAVE_GL
#include "bench_lean_gl.h"
#include "gl/gl_renderer.h"
#endif

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

// [SECTION] Figures of the stages the settings add

// The samples a ray-casting note counts ("volume ray casting: N samples taken; ...").
double rayCastSamples(const std::string& note) {
  unsigned long long n = 0;
  return std::sscanf(note.c_str(), "volume ray casting: %llu", &n) == 1 ? static_cast<double>(n) : 0.0;
}

void printAdditions(const SceneAdditions& added, double milliseconds, const FrameInputs& frame) {
  if (added.particles)
    std::printf("  particles: %llu simulated and made sprites in %.2f ms (median)\n", static_cast<unsigned long long>(added.particles), milliseconds);
  if (added.isosurface)
    std::printf("  marching cubes: %llu triangles in %.2f ms (median), %.3g triangles a second\n",
                static_cast<unsigned long long>(added.isoTriangles), milliseconds, static_cast<double>(added.isoTriangles) / (milliseconds * 1e-3));
  if (added.splats) std::printf("  splats: %llu sprites made in %.2f ms (median)\n", static_cast<unsigned long long>(added.splats), milliseconds);
  if (frame.volume.placed) std::printf("  volume: placed in %.2f ms (median)\n", milliseconds);
}

// [SECTION] The command

struct BenchOptions {
  std::vector<std::string> scenes;
#if FACET_HAVE_GL
  std::vector<std::string> backends{"cpu", "gl", "lean"};
#else
  std::vector<std::string> backends{"cpu"};  // a build without OpenGL measures the CPU alone
#endif
  int frames = 9;
  int warmup = 2;
  int threads = 2;
  std::string size = "1920x1080";
  int startupRuns = 5;
  bool memory = true;
  std::string outDir;         // each backend's image of the last frame, per scene
  bool keepShadowMaps = false;  // time frames that keep the maps drawn before (an orbit in the viewer)
  bool callgrind = false;     // instrument frames only; one scene, one backend
  std::string child;          // internal: "scene:backend" (with --sweep "axis=point:backend"), render, print nothing
  SweepOptions sweep;
};

std::unique_ptr<Renderer> makeBackend(const std::string& backend, int threads) {
  if (backend == "cpu") return makeCpuRenderer(threads);
  if (backend == "cpu4") return makeCpuRenderer(threads, 4);  // Phong on four lanes, as on a CPU without AVX2
  if (backend == "cpu8") return makeCpuRenderer(threads, 8);  // eight, as on a CPU with AVX2 and without AVX-512
  if (backend == "ray") return makeRayRenderer(threads);
#if FACET_HAVE_GL
  if (backend == "gl") return makeGlRenderer(GlContextKind::OsMesa);
  if (backend == "lean") return makeLeanGlRenderer();
  if (backend == "lean-msaa") return makeLeanGlRenderer(LeanSampling::OncePerPixel);
#endif
  throw Error("bench: backend '" + backend + "' is not available in this build");
}

// Why `backend` does not draw the frame (a line of the table), or empty.
std::string skipNote(const std::string& backend, const Scene& scene, const FrameInputs& frame) {
#if FACET_HAVE_GL
  if (backend == "lean" || backend == "lean-msaa") {
    const std::string why = leanUnsupported(scene, frame);
    return why.empty() ? std::string() : backend + ": no minimal program for this scene (" + why + ")";
  }
#else
  (void)scene;
#endif
  // OpenGL does not ray cast volumes; the CPU backend alone draws that scene.
  if (frame.volume.placed && backend != "cpu" && backend != "cpu4" && backend != "cpu8") {
    char line[64];
    std::snprintf(line, sizeof line, "%-4s does not ray cast volumes", backend.c_str());
    return line;
  }
  return {};
}

// The lean peer drew the scene the CPU rasterizer drew: their mean difference
// (R, G, B, 8-bit levels) and the share of pixels where a channel differs by
// more than 16 levels. Small but not zero: the lean shader's maths is not facet's.
void printLeanAgainstCpu(const Image& cpu, const Image& lean) {
  DiffThresholds over16;
  over16.failThreshold = 16.0 / 255.0;
  over16.failPercent = 100.0;
  const DiffResult d = compareImages(cpu, lean, over16);
  const double mean = (d.channels[0].mean + d.channels[1].mean + d.channels[2].mean) / 3.0;
  std::printf("  lean vs cpu: mean difference %.3f levels, %.3f %% of pixels differ by more than 16 levels\n", mean, d.failingPercent);
}

// Whether `backend` leaves the frame out (skipNote says why).
bool skips(const std::string& backend, const Scene& scene, const FrameInputs& frame) { return !skipNote(backend, scene, frame).empty(); }

// What the parent measures (wait4) is this process's peak: it prints nothing.
int runChildMode(const BenchOptions& o, int width, int height) {
  const std::size_t colon = o.child.rfind(':');
  const std::string backend = o.child.substr(colon + 1);
  BenchScene b = o.sweep.enabled ? sweepPointScene(o.sweep, o.child.substr(0, colon)) : makeBenchScene(o.child.substr(0, colon), width, height);
  const PreparedFrame frame = FrameSpine(std::make_shared<const Scene>(std::move(b.scene)), o.threads).frame(b.settings);
  if (skips(backend, *frame.scene, frame.inputs)) return 1;
  std::unique_ptr<Renderer> renderer = makeBackend(backend, o.threads);
  for (int i = 0; i < std::max(1, o.warmup + 1); ++i) (void)renderer->render(*frame.scene, frame.inputs);
  return 0;
}

int runCallgrindMode(const BenchOptions& o, int width, int height) {
  BenchScene b = makeBenchScene(o.scenes.front(), width, height);
  const PreparedFrame frame = FrameSpine(std::make_shared<const Scene>(std::move(b.scene)), o.threads).frame(b.settings);
  std::unique_ptr<Renderer> renderer = makeBackend(o.backends.front(), o.threads);
  for (int i = 0; i < o.warmup; ++i) renderer->recycle(renderer->render(*frame.scene, frame.inputs).image);
  CALLGRIND_ZERO_STATS;
  CALLGRIND_START_INSTRUMENTATION;
  for (int i = 0; i < o.frames; ++i) {
    if (!o.keepShadowMaps) renderer->forgetShadowMaps();
    renderer->recycle(renderer->render(*frame.scene, frame.inputs).image);
  }
  CALLGRIND_STOP_INSTRUMENTATION;
  std::printf("callgrind: %s on %s, %d frame(s) instrumented\n", o.scenes.front().c_str(), o.backends.front().c_str(), o.frames);
  return 0;
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* command = app.add_subcommand("bench", "Benchmark the CPU rasterizer against OpenGL on llvmpipe, same scenes, same threads");
  command->add_option("--scenes", o->scenes, "scenes (default: all twelve; particles-100k and the volume-* ones take seconds a frame, so minutes in all)")
      ->delimiter(',')
      ->check(CLI::IsMember(allSceneNames()));
  command->add_option("--backends", o->backends,
                      "cpu,gl,lean (default all three): lean is llvmpipe with minimal shaders, bench only, an anti-aliased frame's every sample "
                      "shaded (as the course's supersampling); lean-msaa: the same with plain MSAA, shading once a pixel; cpu4, cpu8: the CPU rasterizer shading "
                      "four or eight pixels at a time, as where AVX2 or AVX-512 is missing; and ray: the ray tracer's frame, "
                      "its rays by kind and its BVH, against Embree where built with it")
      ->delimiter(',')
      ->check(CLI::IsMember({"cpu", "cpu4", "cpu8", "gl", "lean", "lean-msaa", "ray"}));
  command->add_option("--frames", o->frames, "timed frames per backend and scene")->check(wholeNumberIn(1, 1000));
  command->add_option("--warmup", o->warmup, "untimed frames first")->check(wholeNumberIn(0, 100));
  command->add_option("--threads", o->threads, "threads of every backend (LP_NUM_THREADS for llvmpipe)")->check(wholeNumberIn(1, kMaxThreads));
  command->add_option("--size", o->size, "image size WxH");
  command->add_option("--startup-runs", o->startupRuns, "runs of `facet render` per backend for the time to the first PNG (0: skip)")
      ->check(CLI::Range(0, 100));
  command->add_flag("!--no-memory", o->memory, "skip the per-backend peak-memory child processes");
  command->add_option("--out", o->outDir, "write each backend's last frame per scene as DIR/<scene>-<backend>.png")
      ->check(CLI::ExistingDirectory);
  command->add_flag("--keep-shadow-maps", o->keepShadowMaps,
                    "time frames that keep the shadow maps drawn before, as a viewer orbit does (default: every frame draws its maps, as `render` does)");
  command->add_flag("--callgrind", o->callgrind, "instrument the timed frames only (run under valgrind --tool=callgrind --instr-atstart=no)");
  command->add_option("--child", o->child, "internal: scene:backend, render for the parent's peak memory")->group("");
  addSweepOptions(*command, o->sweep);
  return [o]() {
    // llvmpipe reads LP_NUM_THREADS when its screen is created: before any context.
    setenv("LP_NUM_THREADS", std::to_string(o->threads).c_str(), 1);
    int width = 0, height = 0;
    parseSize(o->size, width, height);
    if (o->scenes.empty()) o->scenes = allSceneNames();
    if (!o->child.empty()) return runChildMode(*o, width, height);
    if (o->callgrind) return runCallgrindMode(*o, width, height);
    if (o->sweep.enabled)
      return runSweep(o->sweep, {o->backends, o->threads, o->frames, o->warmup, o->memory,
                                 [o](const std::string& backend) { return makeBackend(backend, o->threads); }});
    const std::string self = selfPath();
    // Peak memory first, while this process is small (bench_memory.h).
    std::vector<std::vector<double>> peakMb(o->scenes.size(), std::vector<double>(o->backends.size(), -1.0));
    for (std::size_t s = 0; s < o->scenes.size() && o->memory; ++s)
      for (std::size_t r = 0; r < o->backends.size(); ++r)
        peakMb[s][r] = benchChildPeakMegabytes(
            {"--child", o->scenes[s] + ":" + o->backends[r], "--threads", std::to_string(o->threads), "--size", o->size, "--warmup", "1"});

    std::vector<std::unique_ptr<Renderer>> renderers;
    for (const std::string& backend : o->backends) renderers.push_back(makeBackend(backend, o->threads));
    std::printf("facet bench: %dx%d, %d thread(s), %d warm-up + %d timed frames per backend, alternating\n", width, height, o->threads,
                o->warmup, o->frames);
    int nameWidth = 4;  // the backends' column: lean-msaa widens it
    for (const std::string& backend : o->backends) nameWidth = std::max(nameWidth, static_cast<int>(backend.size()));
    for (std::size_t r = 0; r < renderers.size(); ++r)
      std::printf("  %-*s %s\n", nameWidth, o->backends[r].c_str(), renderers[r]->description().c_str());

    for (std::size_t sceneIndex = 0; sceneIndex < o->scenes.size(); ++sceneIndex) {
      const std::string& name = o->scenes[sceneIndex];
      BenchScene b = makeBenchScene(name, width, height);
      // The frame from the spine: its first run reads the volume (kept for the others) and is not timed.
      FrameSpine spine(std::make_shared<const Scene>(std::move(b.scene)), o->threads);
      const PreparedFrame prepared = spine.frame(b.settings);
      const Scene& scene = *prepared.scene;
      const FrameInputs& frame = prepared.inputs;
      // What the settings add (particles, a volume's mesh or sprites), made anew and timed over the frames as its own stage.
      std::vector<double> adding;
      for (int i = 0; i < o->frames; ++i) {
        spine.forgetScenes();
        const auto start = Clock::now();
        (void)spine.scene(b.settings);
        adding.push_back(millisecondsSince(start));
      }
      std::vector<std::string> skipped(renderers.size());
      std::vector<char> skip(renderers.size(), 0);
      for (std::size_t r = 0; r < renderers.size(); ++r) {
        skipped[r] = skipNote(o->backends[r], scene, frame);
        skip[r] = !skipped[r].empty();
      }
      const double triangles = static_cast<double>(scene.triangleCount());
      std::vector<std::vector<double>> ms(renderers.size()), upload(renderers.size());
      // Each backend's passes in the order it runs them, with their times over the frames: where its frame goes.
      std::vector<std::vector<std::pair<std::string, std::vector<double>>>> passes(renderers.size());
      std::vector<RenderResult> last(renderers.size());
      for (std::size_t r = 0; r < renderers.size(); ++r)
        for (int i = 0; i < o->warmup && !skip[r]; ++i) renderers[r]->recycle(renderers[r]->render(scene, frame).image);
      for (int i = 0; i < o->frames; ++i)
        for (std::size_t r = 0; r < renderers.size(); ++r) {
          if (skip[r]) continue;
          if (!o->keepShadowMaps) renderers[r]->forgetShadowMaps();
          // Every column draws into its previous frame's image, as a loop of frames does (Renderer::recycle).
          renderers[r]->recycle(std::move(last[r].image));
          const auto start = Clock::now();
          last[r] = renderers[r]->render(scene, frame);
          ms[r].push_back(millisecondsSince(start));
          double up = 0;
          for (const PassTiming& t : last[r].timings) {
            if (t.pass == kSceneUploadPass) up = t.milliseconds;
            auto at = std::find_if(passes[r].begin(), passes[r].end(), [&](const auto& p) { return p.first == t.pass; });
            if (at == passes[r].end()) at = passes[r].insert(passes[r].end(), {t.pass, {}});
            at->second.push_back(t.milliseconds);
          }
          upload[r].push_back(up);
        }
      std::printf("\n%s: %.0f triangles, %s shading, %zu light(s), %d shadow map(s) of %d²\n", name.c_str(), triangles,
                  std::string(kShadingModeNames[static_cast<std::size_t>(frame.shading)]).c_str(), frame.lights.size(), frame.shadowLayerCount,
                  frame.shadowLayerCount > 0 ? frame.shadows.mapSize : 0);
      std::printf("  %-*s %10s %31s %8s %8s %11s %7s %8s\n", nameWidth, "", "ms/frame", "min..max (q1..q3)", "Mtri/s", "peak MB", "ms -upload", "vs gl",
                  "vs lean");
      double glMedian = 0, leanMedian = 0;
      for (std::size_t r = 0; r < renderers.size(); ++r) {
        if (skip[r]) continue;
        if (o->backends[r] == "gl") glMedian = summarize(ms[r]).median;
        if (o->backends[r] == "lean") leanMedian = summarize(ms[r]).median;
      }
      printAdditions(prepared.added, summarize(adding).median, frame);
      for (std::size_t r = 0; r < renderers.size(); ++r) {
        if (skip[r]) {
          std::printf("  %s\n", skipped[r].c_str());
          continue;
        }
        const Summary s = summarize(ms[r]);
        std::vector<double> net;
        for (std::size_t i = 0; i < ms[r].size(); ++i) net.push_back(ms[r][i] - upload[r][i]);
        char ratio[32] = "", leanRatio[32] = "";
        if (glMedian > 0 && o->backends[r] != "gl") std::snprintf(ratio, sizeof ratio, "%.2f", s.median / glMedian);
        if (leanMedian > 0 && o->backends[r] != "lean") std::snprintf(leanRatio, sizeof leanRatio, "%.2f", s.median / leanMedian);
        char spread[64];
        std::snprintf(spread, sizeof spread, "%.1f..%.1f (%.1f..%.1f)", s.min, s.max, s.q1, s.q3);
        char row[256];
        std::snprintf(row, sizeof row, "  %-*s %10.2f %31s %8.2f %8.0f %11.2f %7s %8s", nameWidth, o->backends[r].c_str(), s.median, spread,
                      triangles / (s.median * 1e3), peakMb[sceneIndex][r], summarize(net).median, ratio, leanRatio);
        std::string line = row;
        line.erase(line.find_last_not_of(' ') + 1);  // a blank ratio column leaves no trailing spaces
        std::printf("%s\n", line.c_str());
        std::string split;
        for (const auto& [pass, times] : passes[r]) {
          char part[96];
          std::snprintf(part, sizeof part, "%s%s %.1f", split.empty() ? "" : ", ", pass.c_str(), summarize(times).median);
          split += part;
        }
        if (!split.empty()) std::printf("       passes, median ms: %s\n", split.c_str());
        if (!o->outDir.empty()) writePng(o->outDir + "/" + name + "-" + o->backends[r] + ".png", last[r].image);
        for (const std::string& note : last[r].notes)
          if (note.rfind("volume ray casting", 0) == 0)
            std::printf("       %s; %.3g samples a second\n", note.c_str(), rayCastSamples(note) / (s.median * 1e-3));
      }
      const auto drawn = [&](const char* backend) -> const RenderResult* {
        for (std::size_t r = 0; r < renderers.size(); ++r)
          if (o->backends[r] == backend && !skip[r]) return &last[r];
        return nullptr;
      };
      if (const RenderResult *cpu = drawn("cpu"), *lean = drawn("lean"); cpu && lean) printLeanAgainstCpu(cpu->image, lean->image);
      for (const char* narrower : {"cpu4", "cpu8"})
        if (const RenderResult *cpu = drawn("cpu"), *other = drawn(narrower); cpu && other)
          std::printf("  %s vs cpu: %s\n", narrower, other->image == cpu->image ? "the same image, byte for byte" : "DIFFERENT images");
      if (std::find(o->backends.begin(), o->backends.end(), "ray") != o->backends.end()) printRayRates(scene, frame, o->threads, o->frames);
      std::fflush(stdout);
    }

    if (o->startupRuns > 0) {
      std::printf("\ntime to the first PNG: `facet render -o PNG --backend B` (default scene, default settings), %d runs\n", o->startupRuns);
      const std::string png = "/tmp/facet-bench-startup-" + std::to_string(getpid()) + ".png";
      for (const std::string& backend : o->backends) {
        if (backend == "lean" || backend == "lean-msaa") {
          std::printf("  %s  bench only: `facet render` has no lean backend\n", backend.c_str());
          continue;
        }
        if (backend == "cpu4" || backend == "cpu8") {
          std::printf("  %s  bench only: `facet render` shades on the widest lanes the CPU runs\n", backend.c_str());
          continue;
        }
        std::vector<double> runs;
        for (int i = 0; i < o->startupRuns; ++i) {
          const auto start = Clock::now();
          std::vector<std::string> args{self, "render", "--backend", backend, "-o", png};
          if (backend == "cpu" || backend == "ray") args.insert(args.end(), {"--threads", std::to_string(o->threads)});
          if (runChild(args, nullptr) != 0) throw Error("bench: `facet render --backend " + backend + "` failed");
          runs.push_back(millisecondsSince(start));
        }
        const Summary s = summarize(runs);
        std::printf("  %-4s %8.1f ms median, %.1f..%.1f\n", backend.c_str(), s.median, s.min, s.max);
      }
      std::remove(png.c_str());
    }
    return 0;
  };
}

}  // namespace facet
