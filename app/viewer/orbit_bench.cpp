#include "viewer/orbit_bench.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "child_process.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "render/renderer.h"
#include "render_report.h"
#include "sample_summary.h"
#include "settings/settings_json.h"
#include "viewer/camera_controls.h"

namespace facet::viewer {
namespace {

// How many `facet render` processes each headless figure is the median of.
constexpr int kHeadlessRuns = 3;

// The passes of a printed frame: "  lit pass      97.42 ms". Start-up lines are not the frame's.
double framePassesMilliseconds(const std::string& report) {
  static const std::regex line(R"(^  (.+?)\s+([0-9.]+) ms$)");
  double sum = 0;
  bool any = false;
  std::istringstream in(report);
  std::string text;
  std::smatch m;
  while (std::getline(in, text)) {
    if (!std::regex_match(text, m, line)) continue;
    const std::string pass = m[1];
    static const std::set<std::string> notTheFrame{kSceneUploadPass,     kShaderCompilePass, kSceneInputsLine, kGlStartupLine,
                                                   kRendererStartupLine, kPngWriteLine,      kCommandTotalLine};
    if (notTheFrame.count(pass)) continue;
    sum += std::stod(m[2]);
    any = true;
  }
  if (!any) throw Error("view --bench-orbit: `facet render` printed no pass timings");
  return sum;
}

}  // namespace

void orbitBenchStep(ViewerState& state, int frames, float windowHeight) {
  if (state.settings.camera.source == Source::Auto) state.settings = materialize(*state.scene, state.settings, true, false);
  const CameraSettings before = state.settings.camera;
  orbit(state.settings.camera, {2.0f * windowHeight / static_cast<float>(frames), 0.0f}, windowHeight);
  moveDepthRange(state.settings.camera, before, state.sphere);
}

double headlessFrameMilliseconds(const std::string& scenePath, const RenderSettings& settings, const std::string& backend, int runs) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path();
  const std::string stem = "facet-bench-orbit-" + std::to_string(getpid());
  const std::string settingsFile = (folder / (stem + ".json")).string(), png = (folder / (stem + ".png")).string();
  const std::string text = settingsToJson(settings).dump() + "\n";
  writeFileAtomically(settingsFile, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
  std::vector<double> frames;
  std::vector<std::string> args{selfPath(), "render", "--settings", settingsFile, "--backend", backend, "-o", png};
  if (!scenePath.empty()) args.push_back(scenePath);
  for (int i = 0; i < runs; ++i) {
    std::string report;
    if (runChild(args, &report) != 0) {
      std::filesystem::remove(settingsFile);
      throw Error("view --bench-orbit: `facet render --backend " + backend + "` failed");
    }
    frames.push_back(framePassesMilliseconds(report));
  }
  std::filesystem::remove(settingsFile);
  std::filesystem::remove(png);
  return summarize(frames).median;
}

void printOrbitReport(const std::vector<double>& windowMilliseconds, const std::string& shown, int dragPreview, const std::string& scenePath,
                      const RenderSettings& settings) {
  const Summary s = summarize(windowMilliseconds);
  std::printf("orbit: %zu window frames of a %dx%d view, %s, drawn at 1/%d of each side while dragging\n", windowMilliseconds.size(), settings.width,
              settings.height, shown.c_str(), dragPreview);
  std::printf("  %.1f ms a window frame (median; quartiles %.1f..%.1f, range %.1f..%.1f), %.1f frames a second\n", s.median, s.q1, s.q3, s.min,
              s.max, 1000.0 / s.median);
  for (const char* backend : {"gl", "cpu"}) {
    const double headless = headlessFrameMilliseconds(scenePath, settings, backend, kHeadlessRuns);
    std::printf("  headless `facet render --backend %s` frame (median of %d processes): %.1f ms; orbit frame / headless frame = %.3f\n", backend,
                kHeadlessRuns, headless, s.median / headless);
  }
}

}  // namespace facet::viewer
