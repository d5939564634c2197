// The agreement suite: each case in tests/agreement/cases (one JSON file per
// case: a scene and the settings that differ from the defaults) is rendered
// by the OpenGL backend (headless, llvmpipe) and by the CPU reference, the
// two are compared, and both are compared with the committed CPU golden.
//
//   facet_agreement --cases DIR --golden DIR --out DIR [--update-goldens] [--context osmesa|egl]
//
// Prints the figures per case and in total, then "N passed, N failed";
// writes DIR/gl, DIR/cpu and an HTML report in DIR/report. Exit 0 when
// every case passes.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "agreement_thresholds.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "compare/compare_files.h"
#include "compare/diff_format.h"
#include "compare/diff_report_folder.h"
#include "compare/image_diff.h"
#include "cpu/cpu_renderer.h"
#include "image/srgb.h"
#include "gl/gl_renderer.h"
#include "image/png.h"
#include "pipeline/frame_inputs.h"
#include "scene/load_scene.h"
#include "settings/settings_json.h"

namespace fs = std::filesystem;
using namespace facet;

namespace {

constexpr int kGoldenSize = 256;

struct Case {
  std::string name;   // file name without .json
  std::string scene;  // loadScene path, or assimp:RELATIVE
  std::string note;
  RenderSettings settings;
};

Case readCase(const fs::path& file) {
  const std::string text = readFile(file.string(), 1u << 20);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw Error(file.string() + ": not valid JSON (" + e.what() + ")");
  }
  Case c;
  c.name = file.stem().string();
  c.scene = j.value("scene", "");
  c.note = j.value("note", "");
  nlohmann::json settings = j.value("settings", nlohmann::json::object());
  if (!settings.contains("width")) settings["width"] = kGoldenSize;
  if (!settings.contains("height")) settings["height"] = kGoldenSize;
  try {
    c.settings = settingsFromJson(settings);
  } catch (const Error& e) {
    throw Error(file.string() + ": " + e.what());
  }
  return c;
}

Scene sceneOf(const Case& c) {
  const std::string assimp = "assimp:";
  if (c.scene.rfind(assimp, 0) == 0) return loadScene(std::string(FACET_ASSIMP_MODELS) + "/" + c.scene.substr(assimp.size()));
  return loadScene(c.scene);
}

// Pixels that are background in exactly one of the two images.
long coverageMismatches(const Image& a, const Image& b, Rgba8 background) {
  long count = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) count += (a.at(x, y) == background) != (b.at(x, y) == background);
  return count;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"facet agreement suite: OpenGL (llvmpipe) against the CPU reference, and both against the goldens"};
  std::string casesDir, goldenDir, outDir, context = "osmesa";
  bool update = false;
  app.add_option("--cases", casesDir, "folder of case JSON files")->required();
  app.add_option("--golden", goldenDir, "folder of golden PNGs (CPU renders)")->required();
  app.add_option("--out", outDir, "folder for renders and the HTML report")->required();
  app.add_option("--context", context, "osmesa or egl")->check(CLI::IsMember({"osmesa", "egl"}));
  app.add_flag("--update-goldens", update, "write the CPU renders as the new goldens instead of comparing with them");
  CLI11_PARSE(app, argc, argv);

  try {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(casesDir))
      if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) throw Error(casesDir + ": no case files");
    fs::create_directories(fs::path(outDir) / "gl");
    fs::create_directories(fs::path(outDir) / "cpu");
    fs::create_directories(goldenDir);

    auto gl = makeGlRenderer(context == "egl" ? GlContextKind::Egl : GlContextKind::OsMesa);
    auto cpu = makeCpuRenderer(0);
    std::printf("OpenGL: %s\nCPU:    %s\n\n", gl->description().c_str(), cpu->description().c_str());
    std::printf("%-34s %8s %6s %6s %8s %9s %9s %8s  %s\n", "case", "coverage", "max", "rmse", "psnr", ">1 level", "golden", "ms gl/cpu", "verdict");

    const DiffThresholds agreement = agreement::glVersusCpu();
    int passed = 0, failed = 0, tight = 0;
    std::string worstName;
    DiffResult worst;
    std::vector<ReportCase> report;
    createReportFolder((fs::path(outDir) / "report").string());
    for (const fs::path& file : files) {
      const Case c = readCase(file);
      const Scene scene = sceneOf(c);
      const FrameInputs frame = buildFrameInputs(scene, c.settings);
      const auto t0 = std::chrono::steady_clock::now();
      const Image glImage = gl->render(scene, frame).image;
      const auto t1 = std::chrono::steady_clock::now();
      const Image cpuImage = cpu->render(scene, frame).image;
      const auto t2 = std::chrono::steady_clock::now();
      const std::string glPath = (fs::path(outDir) / "gl" / (c.name + ".png")).string();
      const std::string cpuPath = (fs::path(outDir) / "cpu" / (c.name + ".png")).string();
      writePng(glPath, glImage);
      writePng(cpuPath, cpuImage);

      const Rgba8 background = encodePixel(frame.background);
      const long coverage = coverageMismatches(glImage, cpuImage, background);
      const DiffResult d = compareImages(cpuImage, glImage, agreement);
      const bool withinTight = compareImages(cpuImage, glImage, agreement::tight()).status == DiffStatus::Pass;

      // Goldens: the CPU render at 256×256 is the reference image of the case.
      const std::string goldenPath = (fs::path(goldenDir) / (c.name + ".png")).string();
      std::string goldenVerdict = "-";
      bool goldenOk = true;
      if (update) {
        writePng(goldenPath, cpuImage);
        goldenVerdict = "written";
      } else {
        const ComparedFiles vsGolden = compareFiles(c.name, goldenPath, cpuPath, agreement::cpuVersusGolden());
        goldenOk = vsGolden.diffCase.verdict == Verdict::Pass || vsGolden.diffCase.verdict == Verdict::Warn;
        const ComparedFiles glVsGolden = compareFiles(c.name, goldenPath, glPath, agreement);
        goldenOk = goldenOk && (glVsGolden.diffCase.verdict == Verdict::Pass || glVsGolden.diffCase.verdict == Verdict::Warn);
        goldenVerdict = goldenOk ? "ok" : (vsGolden.diffCase.problem.empty() ? "DIFFERS" : "MISSING");
      }

      const bool ok = coverage <= agreement::kMaxCoverageMismatches && d.status != DiffStatus::Fail && goldenOk;
      (ok ? passed : failed) += 1;
      tight += withinTight && coverage == 0;
      if (worstName.empty() || d.failingPercent > worst.failingPercent ||
          (d.failingPercent == worst.failingPercent && d.maxDifference > worst.maxDifference)) {
        worstName = c.name;
        worst = d;
      }
      const double msGl = std::chrono::duration<double, std::milli>(t1 - t0).count();
      const double msCpu = std::chrono::duration<double, std::milli>(t2 - t1).count();
      std::printf("%-34s %8ld %6d %6.3f %8s %8.3f%% %9s %4.0f/%-4.0f %s\n", c.name.c_str(), coverage, d.maxDifference, d.rmse,
                  formatNumber(d.psnr).c_str(), d.failingPercent, goldenVerdict.c_str(), msGl, msCpu, ok ? "pass" : "FAIL");

      const ComparedFiles pair = compareFiles(c.name, cpuPath, glPath, agreement);
      report.push_back(writeReportImages((fs::path(outDir) / "report").string(), static_cast<int>(report.size()), pair, agreement));
    }
    ReportContext reportContext;
    reportContext.expectedSource = "CPU reference (" + cpu->description() + ")";
    reportContext.actualSource = "OpenGL (" + gl->description() + ")";
    reportContext.thresholds = agreement;
    const std::string page = writeReportPage((fs::path(outDir) / "report").string(), report, reportContext);

    std::printf("\ncases: %zu; within the tight target (coverage identical, every pixel within 1 level): %d\n", files.size(), tight);
    std::printf("worst case: %s: %s over 1 level (%.3f%%), max difference %d levels, RMSE %.3f, PSNR %s dB\n", worstName.c_str(),
                formatPixels(worst.failingPixels).c_str(), worst.failingPercent, worst.maxDifference, worst.rmse,
                formatNumber(worst.psnr).c_str());
    std::printf("report: %s\n", page.c_str());
    std::printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
  } catch (const Error& e) {
    std::fprintf(stderr, "facet_agreement: %s\n", e.what());
    return 2;
  }
}
