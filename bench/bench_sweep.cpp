#include "bench_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "bench_memory.h"
#include "sample_summary.h"
#include "svg_plot.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "common/stopwatch.h"
#include "pipeline/frame_spine.h"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kSweepFrames = 3;
constexpr int kSweepWarmup = 1;
const std::vector<std::string> kAxes{"triangles", "pixels", "lights"};
static_assert(kMaxLights >= 8, "the light axis goes up to 8 lights a frame");

// One point of an axis: the sphere scene it renders and its size.
struct SweepPoint {
  std::string axis;
  std::string name;  // unique on its axis; "axis=name" names the point to the memory child
  int level = kSphere100k;
  int spotLights = 0;  // 0: one point light, no shadows
  int mapSize = 2048;
  int width = 1920, height = 1080;
};

// Every point of the chosen axes, in the order the axes were given. The
// quick points keep each axis' shape (how many points, what grows) at sizes
// a test runs in seconds.
std::vector<SweepPoint> pointsOf(const SweepOptions& options) {
  const bool quick = options.quick;
  const int width = quick ? 160 : 1920, height = quick ? 120 : 1080;
  const int level = quick ? 16 : kSphere100k;  // the sphere of the pixel and light axes
  std::vector<SweepPoint> points;
  std::vector<std::string> done;
  for (const std::string& axis : options.axes) {
    if (std::find(done.begin(), done.end(), axis) != done.end()) continue;
    done.push_back(axis);
    if (axis == "triangles") {
      // 4·L·(L-1) triangles: 9 800, 100 488, 998 000, 4 995 224 (quick: 80, 960, 9 800, 100 488).
      using Levels = std::vector<std::pair<std::string, int>>;
      const Levels levels = quick ? Levels{{"80", 5}, {"1k", 16}, {"10k", 50}, {"100k", kSphere100k}}
                                  : Levels{{"10k", 50}, {"100k", kSphere100k}, {"1M", kSphere1M}, {"5M", 1118}};
      for (const auto& [name, l] : levels) points.push_back({axis, name, l, 0, 2048, width, height});
    } else if (axis == "pixels") {
      using Sizes = std::vector<std::pair<int, int>>;
      const Sizes sizes = quick ? Sizes{{40, 30}, {80, 60}, {160, 120}, {320, 240}, {640, 480}}
                                : Sizes{{640, 480}, {1280, 720}, {1920, 1080}, {3840, 2160}, {7680, 4320}};
      for (const auto& [w, h] : sizes) points.push_back({axis, std::to_string(w) + "x" + std::to_string(h), level, 0, 2048, w, h});
    } else if (axis == "lights") {
      for (const int n : {1, 2, 4, 8}) points.push_back({axis, std::to_string(n), level, n, quick ? 128 : 2048, width, height});
    }
  }
  return points;
}

BenchScene sceneOf(const SweepPoint& p) {
  return sphereScene("sweep " + p.axis + "=" + p.name, p.level, p.spotLights, p.width, p.height, p.mapSize);
}

std::string lightsOf(const SweepPoint& p) {
  if (p.spotLights == 0) return "1 point";
  return std::to_string(p.spotLights) + " spot, map " + std::to_string(p.mapSize);
}

// A point's frames on every backend: warm-up first, then the timed frames
// alternating between backends so that background load hits all alike.
// A backend that cannot draw the point gets no times and its message.
struct PointTimes {
  std::vector<double> medianMs;       // NaN where it failed
  std::vector<std::string> failures;  // empty where it drew
};

PointTimes timePoint(BenchScene b, std::vector<std::unique_ptr<Renderer>>& renderers, int warmup, int frames) {
  const PreparedFrame prepared = FrameSpine(std::make_shared<const Scene>(std::move(b.scene))).frame(b.settings);
  PointTimes t{std::vector<double>(renderers.size(), NAN), std::vector<std::string>(renderers.size())};
  std::vector<std::vector<double>> ms(renderers.size());
  const auto draw = [&](std::size_t r, bool timed) {
    if (!t.failures[r].empty()) return;
    try {
      renderers[r]->forgetShadowMaps();  // each frame draws its maps: the lights axis is their cost
      const auto start = Clock::now();
      RenderResult drawn = renderers[r]->render(*prepared.scene, prepared.inputs);
      if (timed) ms[r].push_back(millisecondsSince(start));
      renderers[r]->recycle(std::move(drawn.image));  // the next frame's storage, as bench's scenes do
    } catch (const Error& e) {
      t.failures[r] = e.what();
    }
  };
  for (std::size_t r = 0; r < renderers.size(); ++r)
    for (int i = 0; i < warmup; ++i) draw(r, false);
  for (int i = 0; i < frames; ++i)
    for (std::size_t r = 0; r < renderers.size(); ++r) draw(r, true);
  for (std::size_t r = 0; r < renderers.size(); ++r)
    if (t.failures[r].empty()) t.medianMs[r] = summarize(ms[r]).median;
  return t;
}

std::string cell(double value) {
  if (!std::isfinite(value) || value < 0) return "-";
  char text[32];
  std::snprintf(text, sizeof text, value < 10 ? "%.2f" : "%.1f", value);
  return text;
}

// 100490 as "100k", 9802 as "9.8k", 4995226 as "5M".
std::string triangleCount(double n) {
  char text[32];
  if (n < 1e3) std::snprintf(text, sizeof text, "%.0f", n);
  else if (n < 1e6) std::snprintf(text, sizeof text, "%.3gk", n / 1e3);
  else std::snprintf(text, sizeof text, "%.3gM", n / 1e6);
  return text;
}

// What an axis holds fixed (its first point), in its panels' titles.
std::string panelTitle(const SweepPoint& p, double triangles) {
  const std::string size = std::to_string(p.width) + "x" + std::to_string(p.height);
  if (p.axis == "triangles") return "triangles: " + size + ", 1 point light";
  if (p.axis == "pixels") return "pixels: " + triangleCount(triangles) + " triangles, 1 point light";
  return "spot lights: " + triangleCount(triangles) + " triangles, " + size + ", " + std::to_string(p.mapSize) + "² maps";
}

// Time above memory (when measured), a column per axis; x is the axis' value
// at each point (triangles, megapixels, lights), y a series per backend.
Plot plotOf(const std::vector<SweepPoint>& points, const std::vector<double>& triangles, const std::vector<double>& xs,
            const std::vector<std::vector<double>>& ms, const std::vector<std::vector<double>>& mb, const std::vector<std::string>& backends,
            const std::string& note, bool memory) {
  Plot plot;
  plot.title = "facet bench --sweep: frame time and peak memory by triangles, pixels and lights";
  plot.note = note;
  std::vector<std::string> axes;
  for (const SweepPoint& p : points)
    if (std::find(axes.begin(), axes.end(), p.axis) == axes.end()) axes.push_back(p.axis);
  plot.columns = static_cast<int>(axes.size());
  for (const bool memoryRow : {false, true}) {
    if (memoryRow && !memory) break;
    for (const std::string& axis : axes) {
      PlotPanel panel;
      std::vector<std::size_t> at;
      for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i].axis == axis) at.push_back(i);
      const SweepPoint& first = points[at.front()];
      panel.title = panelTitle(first, triangles[at.front()]);
      const bool log = axis != "lights";
      panel.x.log = panel.y.log = log;
      panel.y.fromZero = !log;
      panel.x.label = axis == "triangles" ? "triangles" : axis == "pixels" ? "megapixels" : "spot lights, each with a shadow map";
      panel.y.label = memoryRow ? "peak MB (a child process)" : "ms per frame (median)";
      for (const std::size_t i : at) {
        char label[32];
        if (axis == "pixels") std::snprintf(label, sizeof label, "%.2g", xs[i]);
        panel.x.ticks.emplace_back(xs[i], axis == "pixels" ? std::string(label) : points[i].name);
      }
      for (std::size_t r = 0; r < backends.size(); ++r) {
        PlotSeries s{backends[r], {}, {}};
        for (const std::size_t i : at) {
          s.x.push_back(xs[i]);
          const double y = memoryRow ? mb[i][r] : ms[i][r];
          s.y.push_back(y > 0 ? y : NAN);
        }
        panel.series.push_back(std::move(s));
      }
      plot.panels.push_back(std::move(panel));
    }
  }
  return plot;
}

}  // namespace

void addSweepOptions(CLI::App& bench, SweepOptions& options) {
  options.frames = bench.get_option("--frames");
  options.warmup = bench.get_option("--warmup");
  CLI::Option* sweep = bench.add_flag("--sweep", options.enabled,
                                      "frame time and peak memory as triangles (10k-5M), pixels (640x480-7680x4320) and spot lights with "
                                      "shadow maps (1-8) grow, per backend; default 3 frames after 1 warm-up");
  for (const char* other : {"--scenes", "--size", "--out", "--callgrind", "--startup-runs"}) sweep->excludes(bench.get_option(other));
  bench.add_option("--sweep-axes", options.axes, "the sweep's axes (default all): triangles,pixels,lights")
      ->delimiter(',')
      ->check(CLI::IsMember(kAxes))
      ->needs(sweep);
  bench.add_flag("--sweep-quick", options.quick, "the same points at tiny sizes (tests): seconds instead of minutes")->needs(sweep);
  bench.add_option("--plot", options.plot, "write the sweep as an SVG plot: ms per frame and peak MB against each axis")->needs(sweep);
}

BenchScene sweepPointScene(const SweepOptions& options, const std::string& point) {
  SweepOptions all = options;
  all.axes = kAxes;
  for (const SweepPoint& p : pointsOf(all))
    if (p.axis + "=" + p.name == point) return sceneOf(p);
  throw UsageError("bench --sweep: no point '" + point + "'");
}

int runSweep(const SweepOptions& options, const SweepRun& run) {
  if (!options.plot.empty()) checkOutputFile(options.plot, {});
  const int frames = options.frames && options.frames->count() > 0 ? run.frames : kSweepFrames;
  const int warmup = options.warmup && options.warmup->count() > 0 ? run.warmup : kSweepWarmup;
  const std::vector<SweepPoint> points = pointsOf(options);
  const std::size_t backends = run.backends.size();
  std::printf("facet bench --sweep: %zu points, %d thread(s), %d warm-up + %d timed frames per backend, alternating\n", points.size(),
              run.threads, warmup, frames);

  // Memory first: a child's figure is never below this process's peak at its spawn.
  std::vector<std::vector<double>> mb(points.size(), std::vector<double>(backends, -1.0));
  if (run.memory) {
    std::printf("peak memory: a child process per point and backend (%zu)\n", points.size() * backends);
    std::fflush(stdout);
    for (std::size_t i = 0; i < points.size(); ++i)
      for (std::size_t r = 0; r < backends; ++r) {
        std::vector<std::string> args{"--sweep", "--child", points[i].axis + "=" + points[i].name + ":" + run.backends[r], "--threads",
                                      std::to_string(run.threads), "--warmup", "1"};
        if (options.quick) args.insert(args.begin() + 1, "--sweep-quick");
        mb[i][r] = benchChildPeakMegabytes(args);
      }
  }

  std::vector<std::unique_ptr<Renderer>> renderers;
  for (const std::string& backend : run.backends) renderers.push_back(run.makeBackend(backend));
  for (std::size_t r = 0; r < backends; ++r) std::printf("  %-4s %s\n", run.backends[r].c_str(), renderers[r]->description().c_str());
  std::printf("\n%-9s %-9s %9s %9s %-16s", "axis", "point", "triangles", "size", "lights");
  for (const std::string& backend : run.backends) std::printf(" %9s %7s", (backend + " ms").c_str(), (backend + " MB").c_str());
  std::printf("\n");
  std::fflush(stdout);

  std::vector<double> triangles(points.size()), xs(points.size());
  std::vector<std::vector<double>> ms(points.size());
  std::vector<std::string> failures;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const SweepPoint& p = points[i];
    BenchScene b = sceneOf(p);
    triangles[i] = static_cast<double>(b.scene.triangleCount());
    xs[i] = p.axis == "triangles" ? triangles[i] : p.axis == "pixels" ? p.width * static_cast<double>(p.height) / 1e6 : p.spotLights;
    const PointTimes t = timePoint(std::move(b), renderers, warmup, frames);
    ms[i] = t.medianMs;
    const std::string size = std::to_string(p.width) + "x" + std::to_string(p.height);
    std::printf("%-9s %-9s %9.0f %9s %-16s", p.axis.c_str(), p.name.c_str(), triangles[i], size.c_str(), lightsOf(p).c_str());
    for (std::size_t r = 0; r < backends; ++r) {
      std::printf(" %9s %7s", cell(ms[i][r]).c_str(), mb[i][r] < 0 ? "-" : std::to_string(static_cast<long>(std::lround(mb[i][r]))).c_str());
      if (!t.failures[r].empty()) failures.push_back(run.backends[r] + " at " + p.axis + "=" + p.name + ": " + t.failures[r]);
    }
    std::printf("\n");
    std::fflush(stdout);
  }
  for (const std::string& f : failures) std::printf("  failed: %s\n", f.c_str());

  if (!options.plot.empty()) {
    char note[256];
    std::snprintf(note, sizeof note,
                  "%d thread(s); median of %d frames after %d warm-up, backends alternating; peak memory: wait4's ru_maxrss of a child "
                  "process per point and backend",
                  run.threads, frames, warmup);
    writeFileAtomically(options.plot, plotSvg(plotOf(points, triangles, xs, ms, mb, run.backends, note, run.memory)));
    std::printf("plot: %s\n", options.plot.c_str());
  }
  return 0;
}

}  // namespace facet
