// facet bench: the CPU reference rasterizer and OpenGL on llvmpipe, side by
// side, on the same scenes at the same thread count.
//
// Index of this file
//   [SECTION] Scenes: built in code, manual camera and lights
//   [SECTION] Memory
//   [SECTION] The command
//
// In one process, for each scene, every backend renders `--warmup` frames,
// then `--frames` frames alternately (cpu, gl, lean, cpu, gl, lean, ...) so
// background load hits them alike; a frame is one Renderer::render call (GL:
// scene upload, both passes and the read-back of the image). `lean` is
// llvmpipe with the plainest programs that draw the same picture
// (bench_lean_gl.h), a floor for what the gl column's contract costs. Peak
// memory is the VmHWM of a child process (this executable, `bench --child
// ...`) that builds one scene and renders it with one backend, so each
// backend's figure is its own. `--callgrind` renders one scene with one
// backend with callgrind's instrumentation switched on around the frames only.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#define CALLGRIND_ZERO_STATS
#endif

#include "child_process.h"
#include "command_line.h"
#include "bench_rays.h"
#include "commands.h"
#include "sample_summary.h"
#include "common/error.h"
#include "compare/image_diff.h"
#include "cpu/cpu_renderer.h"
#include "ray/ray_renderer.h"
#include "image/png.h"
#include "math/transforms.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/scene_additions.h"
#include "scene/default_scene.h"
#include "scene/primitives.h"
#if FACET_HAVE_GL
#include "bench_lean_gl.h"
#include "gl/gl_renderer.h"
#endif

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

// [SECTION] Scenes: built in code, manual camera and lights

struct BenchScene {
  std::string name;
  Scene scene;
  RenderSettings settings;
};

constexpr int kSphere100k = 159;  // 4·159·158 = 100 488 triangles
constexpr int kSphere1M = 500;    // 4·500·499 = 998 000 triangles

RenderSettings manualSettings(int width, int height) {
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.camera.source = Source::Manual;
  s.lightSource = Source::Manual;
  s.shading = ShadingMode::Phong;
  s.shadows.enabled = false;
  s.ray.spheres = false;  // every column draws the same triangles
  return s;
}

// A unit sphere of `level` bands on a ground plane; a point light (no
// shadows), or a spot light with one 2048² map and PCF r = 1.
BenchScene sphereScene(const std::string& name, int level, bool shadows, int width, int height) {
  BenchScene b{name, {}, manualSettings(width, height)};
  b.scene.source = name;
  b.scene.addObject(makeSphere(level), b.scene.addMaterial("sphere", {0.8f, 0.1f, 0.08f}, 0.0f, 0.3f), glm::mat4(1.0f));
  b.scene.addObject(makePlane(1), b.scene.addMaterial("ground", {0.45f, 0.45f, 0.42f}, 0.0f, 0.9f),
            translation({0.0f, -1.0f, 0.0f}) * scaling({4.0f, 1.0f, 4.0f}));
  b.settings.camera.eye = {0.0f, 0.6f, 3.2f};
  b.settings.camera.reference = {0.0f, -0.1f, 0.0f};
  b.settings.camera.near = 0.5f;
  b.settings.camera.far = 20.0f;
  Light light;
  light.position = {-2.0f, 4.0f, 2.5f};
  light.attenuation = {1.0f, 0.0f, 0.002f};
  if (shadows) {
    light.kind = LightKind::Spot;
    light.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 0.0f) - light.position);
    light.spotCutoffDeg = 40.0f;
    b.settings.shadows.enabled = true;
    b.settings.shadows.mapSize = 2048;
    b.settings.shadows.pcfRadius = 1;
  }
  b.settings.lights = {light};
  return b;
}

// Ten screen-filling quads drawn back to front: every pixel shaded ~10 times.
// Blended (material.opacity 0.5), each of those fragments is also blended:
// transparency's per-fragment path, with no visibility-first shortcut.
BenchScene fillScene(const std::string& name, bool blended, int width, int height) {
  BenchScene b{name, {}, manualSettings(width, height)};
  if (blended) b.settings.material.opacity = 0.5f;
  b.scene.source = b.name;
  for (int i = 0; i < 10; ++i) {
    const float z = -9.0f + static_cast<float>(i);  // farthest first
    const float t = static_cast<float>(i) / 9.0f;
    // makePlane lies in y = 0 facing +y; Rx(90°) turns it to face +z, the camera.
    b.scene.addObject(makePlane(1), b.scene.addMaterial("layer " + std::to_string(i), {0.2f + 0.6f * t, 0.5f, 0.8f - 0.6f * t}, 0.0f, 0.5f),
              translation({0.0f, 0.0f, z}) * rotationX(0.5f * std::numbers::pi_v<float>) * scaling({40.0f, 1.0f, 40.0f}));
  }
  b.settings.camera.eye = {0.0f, 0.0f, 2.0f};
  b.settings.camera.reference = {0.0f, 0.0f, 0.0f};
  b.settings.camera.near = 0.5f;
  b.settings.camera.far = 20.0f;
  Light light;
  light.position = {1.0f, 1.5f, 3.0f};
  b.settings.lights = {light};
  return b;
}

// The default scene with its own camera and light written as manual settings;
// with `samples` > 1 anti-aliased (four passes of the camera, one of each shadow map).
BenchScene defaultScene(const std::string& name, int samples, int width, int height) {
  BenchScene b{name, makeDefaultScene(), manualSettings(width, height)};
  b.settings.antialiasing.samples = samples;
  const SceneCamera& camera = b.scene.cameras.front();
  b.settings.camera.eye = camera.eye;
  b.settings.camera.reference = camera.reference;
  b.settings.camera.up = camera.up;
  b.settings.camera.near = camera.near;
  b.settings.camera.far = camera.far.value_or(30.0f);
  b.settings.lights = b.scene.lights;
  b.settings.shadows.enabled = true;  // the default settings: a point light, six 2048² maps, PCF r = 1
  return b;
}

// The default scene's ground with 100k particles alive (40,000 born a second, living 2.5 s, at 3 s).
BenchScene particleScene(const std::string& name, int width, int height) {
  BenchScene b = defaultScene(name, 1, width, height);
  Emitter e;
  e.position = {0.0f, 0.02f, 0.0f};
  e.rate = 40000.0f;
  e.lifetime = 2.5f;
  e.spread = 20.0f;
  e.speed = 4.5f;
  e.startSize = 0.03f;
  e.endSize = 0.06f;
  b.settings.particles = {e};
  b.settings.time = 3.0f;
  return b;
}

// The Marschner-Lobb signal at 256³ drawn by `mode`: the iso-surface at 0.5,
// or its values near 0.5 (a thin shell: splatting's sprites fit the frame budget).
BenchScene volumeScene(const std::string& name, VolumeMode mode, int width, int height) {
  BenchScene b{name, {}, manualSettings(width, height)};
  b.scene.source = name;
  b.settings.volume.file = "builtin:marschner-lobb";
  b.settings.volume.resolution = 256;
  b.settings.volume.mode = mode;
  b.settings.volume.center = {0.0f, 0.0f, 0.0f};
  b.settings.volume.rotation = {-65.0f, 30.0f, 0.0f};
  b.settings.volume.transfer = mode == VolumeMode::Splat ? "0.47 1 0.8 0.5 0, 0.5 1 0.8 0.5 0.6, 0.53 1 0.8 0.5 0"
                                                         : "0.42 0.1 0.3 0.9 0, 0.5 0.95 0.7 0.25 0.5, 0.75 0.85 0.25 0.1 0.25, 1 1 0.95 0.9 0.5";
  b.settings.volume.isoValue = 0.5f;
  b.settings.camera.eye = {0.0f, 1.6f, 3.0f};
  b.settings.camera.reference = {0.0f, -0.05f, 0.0f};
  Light light;
  light.position = {-2.0f, 4.0f, 2.5f};
  b.settings.lights = {light};
  return b;
}

std::vector<std::string> allSceneNames() {
  return {"sphere-100k", "sphere-1m",     "sphere-100k-shadow", "sphere-1m-shadow", "fill-10x",     "fill-10x-blended", "default",
          "default-aa4", "particles-100k", "volume-raycast-256", "volume-splat-256", "volume-isosurface-256"};
}

BenchScene makeBenchScene(const std::string& name, int width, int height) {
  if (name == "sphere-100k") return sphereScene(name, kSphere100k, false, width, height);
  if (name == "sphere-1m") return sphereScene(name, kSphere1M, false, width, height);
  if (name == "sphere-100k-shadow") return sphereScene(name, kSphere100k, true, width, height);
  if (name == "sphere-1m-shadow") return sphereScene(name, kSphere1M, true, width, height);
  if (name == "fill-10x") return fillScene(name, false, width, height);
  if (name == "fill-10x-blended") return fillScene(name, true, width, height);
  if (name == "default") return defaultScene(name, 1, width, height);
  if (name == "default-aa4") return defaultScene(name, 4, width, height);
  if (name == "particles-100k") return particleScene(name, width, height);
  if (name == "volume-raycast-256") return volumeScene(name, VolumeMode::Raycast, width, height);
  if (name == "volume-splat-256") return volumeScene(name, VolumeMode::Splat, width, height);
  if (name == "volume-isosurface-256") return volumeScene(name, VolumeMode::Isosurface, width, height);
  throw Error("bench: unknown scene '" + name + "'");
}

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

// [SECTION] Memory

long statusKilobytes(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::string prefix = std::string(key) + ":";
  while (std::getline(in, line))
    if (line.rfind(prefix, 0) == 0) return std::atol(line.c_str() + prefix.size());
  return -1;
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
  std::string child;          // internal: "scene:backend", print VmHWM
};

std::unique_ptr<Renderer> makeBackend(const std::string& backend, int threads) {
  if (backend == "cpu") return makeCpuRenderer(threads);
  if (backend == "ray") return makeRayRenderer(threads);
#if FACET_HAVE_GL
  if (backend == "gl") return makeGlRenderer(GlContextKind::OsMesa);
  if (backend == "lean") return makeLeanGlRenderer();
#endif
  throw Error("bench: backend '" + backend + "' is not available in this build");
}

// Why `backend` does not draw the frame (a line of the table), or empty.
std::string skipNote(const std::string& backend, const Scene& scene, const FrameInputs& frame) {
#if FACET_HAVE_GL
  if (backend == "lean") {
    const std::string why = leanUnsupported(scene, frame);
    return why.empty() ? std::string() : "lean: no minimal program for this scene (" + why + ")";
  }
#else
  (void)scene;
#endif
  // OpenGL does not ray cast volumes; the CPU backend alone draws that scene.
  if (frame.volume.placed && backend != "cpu") {
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

int runChildMode(const BenchOptions& o, int width, int height) {
  const std::size_t colon = o.child.find(':');
  const BenchScene b = makeBenchScene(o.child.substr(0, colon), width, height);
  const FrameInputs frame = buildFrameInputs(b.scene, b.settings);
  const long before = statusKilobytes("VmHWM");
  std::unique_ptr<Renderer> renderer = makeBackend(o.child.substr(colon + 1), o.threads);
  for (int i = 0; i < std::max(1, o.warmup + 1); ++i) (void)renderer->render(b.scene, frame);
  std::printf("%ld %ld\n", before, statusKilobytes("VmHWM"));
  return 0;
}

int runCallgrindMode(const BenchOptions& o, int width, int height) {
  const BenchScene b = makeBenchScene(o.scenes.front(), width, height);
  const FrameInputs frame = buildFrameInputs(b.scene, b.settings);
  std::unique_ptr<Renderer> renderer = makeBackend(o.backends.front(), o.threads);
  for (int i = 0; i < o.warmup; ++i) (void)renderer->render(b.scene, frame);
  CALLGRIND_ZERO_STATS;
  CALLGRIND_START_INSTRUMENTATION;
  for (int i = 0; i < o.frames; ++i) {
    if (!o.keepShadowMaps) renderer->forgetShadowMaps();
    (void)renderer->render(b.scene, frame);
  }
  CALLGRIND_STOP_INSTRUMENTATION;
  std::printf("callgrind: %s on %s, %d frame(s) instrumented\n", o.scenes.front().c_str(), o.backends.front().c_str(), o.frames);
  return 0;
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* command = app.add_subcommand("bench", "Benchmark the CPU rasterizer against OpenGL on llvmpipe, same scenes, same threads");
  command->add_option("--scenes", o->scenes, "scenes (default: all): sphere-100k sphere-1m sphere-100k-shadow sphere-1m-shadow fill-10x fill-10x-blended default default-aa4")
      ->delimiter(',')
      ->check(CLI::IsMember(allSceneNames()));
  command->add_option("--backends", o->backends,
                      "cpu,gl,lean (default all three): lean is llvmpipe with minimal shaders, bench only; and ray: the ray tracer's frame, "
                      "its rays by kind and its BVH, against Embree where built with it")
      ->delimiter(',')
      ->check(CLI::IsMember({"cpu", "gl", "lean", "ray"}));
  command->add_option("--frames", o->frames, "timed frames per backend and scene")->check(wholeNumberIn(1, 1000));
  command->add_option("--warmup", o->warmup, "untimed frames first")->check(wholeNumberIn(0, 100));
  command->add_option("--threads", o->threads, "threads of every backend (LP_NUM_THREADS for llvmpipe)")->check(wholeNumberIn(1, 256));
  command->add_option("--size", o->size, "image size WxH");
  command->add_option("--startup-runs", o->startupRuns, "runs of `facet render` per backend for the time to the first PNG (0: skip)")
      ->check(CLI::Range(0, 100));
  command->add_flag("!--no-memory", o->memory, "skip the per-backend peak-memory child processes");
  command->add_option("--out", o->outDir, "write each backend's last frame per scene as DIR/<scene>-<backend>.png")
      ->check(CLI::ExistingDirectory);
  command->add_flag("--keep-shadow-maps", o->keepShadowMaps,
                    "time frames that keep the shadow maps drawn before, as a viewer orbit does (default: every frame draws its maps, as `render` does)");
  command->add_flag("--callgrind", o->callgrind, "instrument the timed frames only (run under valgrind --tool=callgrind --instr-atstart=no)");
  command->add_option("--child", o->child, "internal: scene:backend, print VmHWM")->group("");
  return [o]() {
    // llvmpipe reads LP_NUM_THREADS when its screen is created: before any context.
    setenv("LP_NUM_THREADS", std::to_string(o->threads).c_str(), 1);
    int width = 0, height = 0;
    parseSize(o->size, width, height);
    if (o->scenes.empty()) o->scenes = allSceneNames();
    if (!o->child.empty()) return runChildMode(*o, width, height);
    if (o->callgrind) return runCallgrindMode(*o, width, height);

    std::vector<std::unique_ptr<Renderer>> renderers;
    for (const std::string& backend : o->backends) renderers.push_back(makeBackend(backend, o->threads));
    std::printf("facet bench: %dx%d, %d thread(s), %d warm-up + %d timed frames per backend, alternating\n", width, height, o->threads,
                o->warmup, o->frames);
    for (std::size_t r = 0; r < renderers.size(); ++r) std::printf("  %-4s %s\n", o->backends[r].c_str(), renderers[r]->description().c_str());
    const std::string self = selfPath();

    for (const std::string& name : o->scenes) {
      BenchScene b = makeBenchScene(name, width, height);
      // What the settings add (particles, a volume's mesh or sprites), timed over the frames as its own stage.
      // The first run reads the volume (kept for the others) and is not timed.
      std::vector<double> adding;
      SceneAdditions added;
      Scene base = b.scene;
      const RenderSettings asked = b.settings;
      for (int i = 0; i <= o->frames; ++i) {
        b.scene = base;
        const auto start = Clock::now();
        b.settings = addVolumeAndParticles(b.scene, asked, added, o->threads);
        if (i > 0) adding.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        base.volume = b.scene.volume;
      }
      const FrameInputs frame = buildFrameInputs(b.scene, b.settings);
      std::vector<std::string> skipped(renderers.size());
      std::vector<char> skip(renderers.size(), 0);
      for (std::size_t r = 0; r < renderers.size(); ++r) {
        skipped[r] = skipNote(o->backends[r], b.scene, frame);
        skip[r] = !skipped[r].empty();
      }
      const double triangles = static_cast<double>(b.scene.triangleCount());
      std::vector<std::vector<double>> ms(renderers.size()), upload(renderers.size());
      // Each backend's passes in the order it runs them, with their times over the frames: where its frame goes.
      std::vector<std::vector<std::pair<std::string, std::vector<double>>>> passes(renderers.size());
      std::vector<RenderResult> last(renderers.size());
      for (std::size_t r = 0; r < renderers.size(); ++r)
        for (int i = 0; i < o->warmup && !skip[r]; ++i) (void)renderers[r]->render(b.scene, frame);
      for (int i = 0; i < o->frames; ++i)
        for (std::size_t r = 0; r < renderers.size(); ++r) {
          if (skip[r]) continue;
          if (!o->keepShadowMaps) renderers[r]->forgetShadowMaps();
          const auto start = Clock::now();
          last[r] = renderers[r]->render(b.scene, frame);
          ms[r].push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
          double up = 0;
          for (const PassTiming& t : last[r].timings) {
            if (t.pass == "scene upload") up = t.milliseconds;
            auto at = std::find_if(passes[r].begin(), passes[r].end(), [&](const auto& p) { return p.first == t.pass; });
            if (at == passes[r].end()) at = passes[r].insert(passes[r].end(), {t.pass, {}});
            at->second.push_back(t.milliseconds);
          }
          upload[r].push_back(up);
        }
      std::printf("\n%s: %.0f triangles, %s shading, %zu light(s), %d shadow map(s) of %d²\n", name.c_str(), triangles,
                  std::string(kShadingModeNames[static_cast<std::size_t>(frame.shading)]).c_str(), frame.lights.size(), frame.shadowLayerCount,
                  frame.shadowLayerCount > 0 ? frame.shadows.mapSize : 0);
      std::printf("  %-4s %10s %31s %8s %8s %11s %7s %8s\n", "", "ms/frame", "min..max (q1..q3)", "Mtri/s", "peak MB", "ms -upload", "vs gl",
                  "vs lean");
      double glMedian = 0, leanMedian = 0;
      for (std::size_t r = 0; r < renderers.size(); ++r) {
        if (skip[r]) continue;
        if (o->backends[r] == "gl") glMedian = summarize(ms[r]).median;
        if (o->backends[r] == "lean") leanMedian = summarize(ms[r]).median;
      }
      printAdditions(added, summarize(adding).median, frame);
      for (std::size_t r = 0; r < renderers.size(); ++r) {
        if (skip[r]) {
          std::printf("  %s\n", skipped[r].c_str());
          continue;
        }
        const Summary s = summarize(ms[r]);
        std::vector<double> net;
        for (std::size_t i = 0; i < ms[r].size(); ++i) net.push_back(ms[r][i] - upload[r][i]);
        double peakMb = -1;
        if (o->memory) {
          std::string out;
          if (runChild({self, "bench", "--child", name + ":" + o->backends[r], "--threads", std::to_string(o->threads), "--size", o->size,
                        "--warmup", "1"},
                       &out) == 0) {
            long before = 0, after = 0;
            if (std::sscanf(out.c_str(), "%ld %ld", &before, &after) == 2) peakMb = static_cast<double>(after) / 1024.0;
          }
        }
        char ratio[32] = "", leanRatio[32] = "";
        if (glMedian > 0 && o->backends[r] != "gl") std::snprintf(ratio, sizeof ratio, "%.2f", s.median / glMedian);
        if (leanMedian > 0 && o->backends[r] != "lean") std::snprintf(leanRatio, sizeof leanRatio, "%.2f", s.median / leanMedian);
        char spread[64];
        std::snprintf(spread, sizeof spread, "%.1f..%.1f (%.1f..%.1f)", s.min, s.max, s.q1, s.q3);
        char row[256];
        std::snprintf(row, sizeof row, "  %-4s %10.2f %31s %8.2f %8.0f %11.2f %7s %8s", o->backends[r].c_str(), s.median, spread,
                      triangles / (s.median * 1e3), peakMb, summarize(net).median, ratio, leanRatio);
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
      if (std::find(o->backends.begin(), o->backends.end(), "ray") != o->backends.end()) printRayRates(b.scene, frame, o->threads, o->frames);
      std::fflush(stdout);
    }

    if (o->startupRuns > 0) {
      std::printf("\ntime to the first PNG: `facet render -o PNG --backend B` (default scene, default settings), %d runs\n", o->startupRuns);
      const std::string png = "/tmp/facet-bench-startup-" + std::to_string(getpid()) + ".png";
      for (const std::string& backend : o->backends) {
        if (backend == "lean") {
          std::printf("  lean  bench only: `facet render` has no lean backend\n");
          continue;
        }
        std::vector<double> runs;
        for (int i = 0; i < o->startupRuns; ++i) {
          const auto start = Clock::now();
          std::vector<std::string> args{self, "render", "--backend", backend, "-o", png};
          if (backend == "cpu" || backend == "ray") args.insert(args.end(), {"--threads", std::to_string(o->threads)});
          if (runChild(args, nullptr) != 0) throw Error("bench: `facet render --backend " + backend + "` failed");
          runs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
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
