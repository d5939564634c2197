#pragma once
// facet bench --sweep: how a frame's time and memory grow with triangles,
// pixels and lights, for each backend, as a table and an SVG plot.
//
// Three axes, each from the sphere on a ground plane (bench_scenes.h):
//  - triangles: ~10k, 100k, 1M and 5M triangles, 1920x1080, one point light,
//    no shadows (10M would need 1.7 GB of vertex and triangle buffers, more
//    than a frame may take: kFrameMemoryBudget);
//  - pixels: the 100k sphere at 640x480 to 7680x4320 (8K);
//  - lights: the 100k sphere at 1920x1080 lit by 1, 2, 4 and 8 spot lights
//    (kMaxLights), each with a 2048² shadow map and PCF r = 1.
// `--sweep-quick` keeps the points' shape at tiny sizes (tests). Peak
// memory comes first, a child process per point and backend, while this
// process is still small (bench_memory.h); then each point's frames,
// backends alternating as in the rest of bench.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench_scenes.h"
#include "render/renderer.h"

namespace facet {

struct SweepOptions {
  bool enabled = false;                                       // --sweep
  std::vector<std::string> axes{"triangles", "pixels", "lights"};  // --sweep-axes
  bool quick = false;                                         // --sweep-quick
  std::string plot;                                           // --plot FILE.svg
  // bench's own --frames and --warmup: the sweep has its own defaults unless they are given.
  const CLI::Option* frames = nullptr;
  const CLI::Option* warmup = nullptr;
};

// Adds --sweep, --sweep-axes, --sweep-quick and --plot to the bench command,
// whose --frames, --warmup and the options the sweep does not take
// (--scenes, --size, --out, --callgrind, --startup-runs) must exist already.
void addSweepOptions(CLI::App& bench, SweepOptions& options);

// What the sweep takes from the rest of bench.
struct SweepRun {
  std::vector<std::string> backends;
  int threads = 2;
  int frames = 3;  // used when --frames is given
  int warmup = 1;  // used when --warmup is given
  bool memory = true;
  std::function<std::unique_ptr<Renderer>(const std::string& backend)> makeBackend;
};

// Runs the sweep: prints the table, writes the plot when asked (checked
// before any work; written whole or not at all). Returns the exit status.
int runSweep(const SweepOptions& options, const SweepRun& run);

// The scene of one point named "axis=point" (the table's first two
// columns, e.g. "lights=4"), as the sweep's memory child builds it.
// Throws facet::UsageError for a point the sweep does not have.
BenchScene sweepPointScene(const SweepOptions& options, const std::string& point);

}  // namespace facet
