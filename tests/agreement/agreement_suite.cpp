// The agreement suite: each case in tests/agreement/cases (one JSON file per
// case: a scene, the settings that differ from the defaults, and what the
// case is for) is rendered by the OpenGL backend (headless, llvmpipe) and by
// the CPU reference. The two must keep the same triangle at every pixel
// (FrameOutput::TriangleIds) and write the same bytes
// (renderer/compare/backend_agreement.h), and both must equal the committed
// CPU golden. Every z-buffer case is also drawn by the CPU's scanline
// z-buffer (hsr = scanline), which must keep the same triangle and write the
// same bytes as the CPU's z-buffer, and the two backends' depth complexity
// (FrameOutput::FragmentCounts) must be equal at every pixel. A case may allow a measured difference only by naming it:
//   "allow": {"maxDifference": LEVELS, "maxPixels": N, "reason": "why"}
// A case may name a stage of the frame (render/stage.h) instead of the image:
//   "stage": "depth" | "shadow-map" | "normals" | "light-N" | "overdraw"
// whose images are compared as the frame's are, and whose data (the window z
// of the z-buffer and of the shadow maps, the normals' floats) must be equal
// bit for bit.
//
//   facet_agreement --cases DIR --golden DIR --out DIR [--case NAME | --summary] [--update-goldens] [--context osmesa|egl]
//
// Prints the figures per case and in total (bit-identical cases out of N,
// the worst pixel), then "N passed, N failed"; writes OUT/gl, OUT/cpu, each
// case's figures in OUT/figures and an HTML report in OUT/report. With
// --case, that case alone and its line: ctest runs each case as its own
// entry, agreement:NAME, in parallel; then --summary renders nothing and
// prints the table, the totals and the report from the figures the cases
// left. Exit 0 when every case run passes, 1 when one fails, 2 when a case
// file is wrong.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/stopwatch.h"
#include "compare/backend_agreement.h"
#include "compare/compare_files.h"
#include "compare/diff_format.h"
#include "compare/diff_report_folder.h"
#include "compare/image_diff.h"
#include "cpu/cpu_renderer.h"
#include "gl/gl_renderer.h"
#include "image/png.h"
#include "pipeline/frame_inputs.h"
#include "pipeline/frame_spine.h"
#include "scene/load_scene.h"
#include "render/stage.h"
#include "settings/settings_json.h"

namespace fs = std::filesystem;
using namespace facet;

namespace {

constexpr int kGoldenSize = 256;  // pixels a side, unless the case sets width and height

// A difference a case allows, with its reason (measured, written down).
struct Allowance {
  int maxDifference = 0;  // 8-bit levels
  long maxPixels = 0;
  std::string reason;
};

struct Case {
  std::string name;   // file name without .json
  std::string scene;  // loadScene path, assimp:RELATIVE or assets:RELATIVE
  std::string note;
  RenderSettings settings;
  std::optional<Allowance> allow;
  Stage stage;  // the image unless the case names another
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
  if (c.note.empty()) throw Error(file.string() + ": 'note': say what the case is for");
  nlohmann::json settings = j.value("settings", nlohmann::json::object());
  // "settingsFile": an assets settings file (assets:NAME) the case's own settings are laid over.
  if (j.contains("settingsFile")) {
    const std::string name = j["settingsFile"].get<std::string>(), local = "assets:";
    const std::string path = name.rfind(local, 0) == 0 ? std::string(FACET_ASSETS) + "/" + name.substr(local.size()) : name;
    nlohmann::json base = settingsToJson(loadSettingsFile(path));
    base.merge_patch(settings);
    settings = std::move(base);
  }
  if (!settings.contains("width")) settings["width"] = kGoldenSize;
  if (!settings.contains("height")) settings["height"] = kGoldenSize;
  try {
    c.settings = settingsFromJson(settings);
  } catch (const Error& e) {
    throw Error(file.string() + ": " + e.what());
  }
  if (j.contains("allow")) {
    const nlohmann::json& a = j["allow"];
    Allowance allow;
    try {
      allow.maxDifference = a.at("maxDifference").get<int>();
      allow.maxPixels = a.at("maxPixels").get<long>();
      allow.reason = a.at("reason").get<std::string>();
    } catch (const nlohmann::json::exception&) {
      throw Error(file.string() + ": 'allow' needs maxDifference (levels), maxPixels and the reason, measured");
    }
    if (allow.reason.empty() || allow.maxDifference < 1 || allow.maxDifference > 255 || allow.maxPixels < 1)
      throw Error(file.string() + ": 'allow' needs a reason, maxDifference in 1..255 and maxPixels of at least 1");
    c.allow = allow;
  }
  if (j.contains("stage")) {
    if (!j["stage"].is_string()) throw Error(file.string() + ": 'stage': expected a string such as \"depth\"");
    try {
      c.stage = parseStage(j["stage"].get<std::string>());
    } catch (const Error& e) {
      throw Error(file.string() + ": 'stage': " + e.what());
    }
  }
  for (const auto& [key, value] : j.items())
    if (key != "scene" && key != "note" && key != "settings" && key != "settingsFile" && key != "allow" && key != "stage")
      throw Error(file.string() + ": '" + key + "': unknown key");
  return c;
}

// The case's frame from the spine (pipeline/frame_spine.h): its scene with the
// maps, volume and particles its settings add (an "assets:" file name there
// is read from the assets folder, as scenes are), and the settings it is
// built with (the camera the sprites face resolved).
PreparedFrame frameOf(Case& c, const std::string& assets) {
  const std::string assimp = "assimp:", local = "assets:";
  const auto resolve = [&](const std::string& name) { return name.rfind(local, 0) == 0 ? assets + "/" + name.substr(local.size()) : name; };
  const std::string path =
      c.scene.rfind(assimp, 0) == 0 ? std::string(FACET_ASSIMP_MODELS) + "/" + c.scene.substr(assimp.size()) : resolve(c.scene);
  c.settings.environment.map = resolve(c.settings.environment.map);
  c.settings.material.displacementMap = resolve(c.settings.material.displacementMap);
  c.settings.material.bumpMap = resolve(c.settings.material.bumpMap);
  PreparedFrame prepared = FrameSpine(std::make_shared<const Scene>(loadScene(path))).frame(c.settings);
  c.settings = prepared.settings;
  return prepared;
}

// The bar of a case: every byte equal, or the case's allowance.
DiffThresholds thresholdsOf(const Case& c) {
  DiffThresholds t = backendAgreement();
  if (c.allow) {
    const double pixels = static_cast<double>(c.settings.width) * c.settings.height;
    t.failPercent = 100.0 * static_cast<double>(c.allow->maxPixels) / pixels;
    t.hardFail = c.allow->maxDifference / 255.0;
  }
  return t;
}

// Pixels whose visible triangle differs between the two backends.
long triangleMismatches(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b, long& covered) {
  long count = 0;
  covered = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    count += a[i] != b[i];
    covered += a[i] != 0;
  }
  return a.size() == b.size() ? count : static_cast<long>(std::max(a.size(), b.size()));
}

bool passes(const ComparedFiles& compared) { return compared.diffCase.verdict == Verdict::Pass; }

// Values whose bits differ (every value when the sizes differ).
template <class T>
long bitMismatches(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return static_cast<long>(std::max(a.size(), b.size()));
  long count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) count += std::memcmp(&a[i], &b[i], sizeof(T)) != 0;
  return count;
}

// The stage's data from both backends, bit for bit: window z, shadow-map texels, normals. 0 for the other stages.
long stageDataMismatches(Stage stage, Renderer& gl, Renderer& cpu, const Scene& scene, const FrameInputs& frame) {
  const auto both = [&](FrameOutput output) { return std::pair(gl.render(scene, frame, {output}), cpu.render(scene, frame, {output})); };
  switch (stage.kind) {
    case StageKind::Depth: {
      const auto [a, b] = both(FrameOutput::Depth);
      return bitMismatches(*a.depth, *b.depth);
    }
    case StageKind::Normals: {
      const auto [a, b] = both(FrameOutput::Normals);
      return bitMismatches(*a.normals, *b.normals);
    }
    case StageKind::ShadowMap: {
      const auto [drawnA, drawnB] = both(FrameOutput::ShadowMaps);
      const ShadowMapTexels &a = *drawnA.shadowMaps, &b = *drawnB.shadowMaps;
      return a.size != b.size || a.layers != b.layers ? static_cast<long>(std::max(a.texels.size(), b.texels.size()) + 1) : bitMismatches(a.texels, b.texels);
    }
    default: return 0;
  }
}

// Which triangle each pixel keeps, as `renderer` draws the frame.
std::vector<std::uint32_t> trianglesOf(Renderer& renderer, const Scene& scene, const FrameInputs& frame) {
  return *renderer.render(scene, frame, {FrameOutput::TriangleIds}).triangleIds;
}


// Where a run reads and writes.
struct Folders {
  std::string golden, out, assets;
  bool update = false;  // write the CPU renders as the goldens
};

// What the summary needs of a case, which its own run leaves in
// OUT/figures/NAME.json: ctest runs every case as an entry of its own
// (agreement:NAME), in its own process, and the summary after them all.
struct Figures {
  std::string row;  // the case's line of the table
  bool pass = false;
  bool sameTriangle = false;        // the same triangle at every pixel
  bool countsEqual = false;         // the same fragment count at every pixel
  std::optional<bool> scanlineSame;  // z-buffer cases: the scanline z-buffer kept the same triangles and bytes
  std::string gl, cpu;               // the backends' descriptions
};

fs::path figuresPath(const std::string& out, const std::string& name) { return fs::path(out) / "figures" / (name + ".json"); }

void writeFigures(const std::string& out, const std::string& name, const Figures& f) {
  nlohmann::json j = {{"row", f.row}, {"pass", f.pass}, {"sameTriangle", f.sameTriangle}, {"countsEqual", f.countsEqual}, {"gl", f.gl}, {"cpu", f.cpu}};
  j["scanlineSame"] = f.scanlineSame ? nlohmann::json(*f.scanlineSame) : nlohmann::json();
  writeFileAtomically(figuresPath(out, name).string(), j.dump(1) + "\n");
}

// The case's figures, or none when its run left none (it did not run, or ended before the end).
std::optional<Figures> readFigures(const std::string& out, const std::string& name) {
  const fs::path path = figuresPath(out, name);
  if (!fs::exists(path)) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(readFile(path.string(), 1u << 20));
    Figures f{j.at("row").get<std::string>(), j.at("pass").get<bool>(), j.at("sameTriangle").get<bool>(), j.at("countsEqual").get<bool>(), {},
              j.at("gl").get<std::string>(), j.at("cpu").get<std::string>()};
    if (!j.at("scanlineSame").is_null()) f.scanlineSame = j["scanlineSame"].get<bool>();
    return f;
  } catch (const nlohmann::json::exception& e) {
    throw Error(path.string() + ": not the figures of a case (" + e.what() + ")");
  }
}

template <class... Args>
std::string formatted(const char* format, Args... args) {
  std::string text(static_cast<std::size_t>(std::snprintf(nullptr, 0, format, args...)), '\0');
  std::snprintf(text.data(), text.size() + 1, format, args...);
  return text;
}

void printHeader(const std::string& gl, const std::string& cpu) {
  std::printf("OpenGL: %s\nCPU:    %s\n\n", gl.c_str(), cpu.c_str());
  std::printf("%-34s %9s %9s %9s %5s %7s %8s %9s  %s\n", "case", "size", "triangle", "differing", "max", "golden", "scanline", "ms gl/cpu",
              "verdict");
}

// Renders one case with both backends (and the scanline z-buffer), holds
// them to each other and to the golden, writes OUT/gl/NAME.png,
// OUT/cpu/NAME.png and the case's figures, and returns them.
Figures runCase(Case& c, Renderer& gl, Renderer& cpu, const Folders& folders) {
  PreparedFrame prepared = frameOf(c, folders.assets);
  prepared.inputs.lineEnds = lineEndTestOf(gl.description());  // the CPU's segment ends as this llvmpipe draws them
  const Scene& scene = *prepared.scene;
  const FrameInputs& frame = prepared.inputs;
  const DiffThresholds thresholds = thresholdsOf(c);
  const auto glStart = std::chrono::steady_clock::now();
  const Image glImage = renderStage(gl, scene, frame, c.stage).image;
  const double msGl = millisecondsSince(glStart);
  const auto cpuStart = std::chrono::steady_clock::now();
  const Image cpuImage = renderStage(cpu, scene, frame, c.stage).image;
  const double msCpu = millisecondsSince(cpuStart);
  long covered = 0;
  const long mismatches = triangleMismatches(trianglesOf(gl, scene, frame), trianglesOf(cpu, scene, frame), covered);
  const long dataMismatches = stageDataMismatches(c.stage, gl, cpu, scene, frame);
  if (covered == 0) {  // lines, points and blended surfaces keep no triangle: what they drew is what differs from the frame without them
    FrameInputs empty = frame;
    empty.instances.clear();
    empty.paintersOrder.clear();
    empty.transparentOrder.clear();
    const Image background = cpu.render(scene, empty).image;
    for (int y = 0; y < cpuImage.height(); ++y)
      for (int x = 0; x < cpuImage.width(); ++x) {
        const Rgba8 a = cpuImage.at(x, y), b = background.at(x, y);
        covered += a.r != b.r || a.g != b.g || a.b != b.b;
      }
  }
  const std::string glPath = (fs::path(folders.out) / "gl" / (c.name + ".png")).string();
  const std::string cpuPath = (fs::path(folders.out) / "cpu" / (c.name + ".png")).string();
  writePng(glPath, glImage);
  writePng(cpuPath, cpuImage);
  const DiffResult d = compareImages(cpuImage, glImage, thresholds);

  // Goldens: the CPU render is the reference image of the case; both backends must equal it.
  const std::string goldenPath = (fs::path(folders.golden) / (c.name + ".png")).string();
  std::string goldenVerdict = "-";
  bool goldenOk = true;
  if (folders.update) {
    writePng(goldenPath, cpuImage);
    goldenVerdict = "written";
  } else {
    const ComparedFiles cpuVsGolden = compareFiles(c.name, goldenPath, cpuPath, backendAgreement());
    const ComparedFiles glVsGolden = compareFiles(c.name, goldenPath, glPath, thresholds);
    goldenOk = passes(cpuVsGolden) && (passes(glVsGolden) || (c.allow && glVsGolden.diffCase.verdict == Verdict::Warn));
    goldenVerdict = goldenOk ? "ok" : (cpuVsGolden.diffCase.problem.empty() ? "DIFFERS" : "MISSING");
  }

  Figures f;
  f.gl = gl.description();
  f.cpu = cpu.description();

  // The scanline z-buffer (CPU) keeps what the z-buffer keeps: the same triangle and the same bytes at every pixel.
  std::string scanline = "-";
  if (c.settings.hsr == HiddenSurface::ZBuffer) {
    RenderSettings rows = c.settings;
    rows.hsr = HiddenSurface::Scanline;
    const FrameInputs rowFrame = buildFrameInputs(scene, rows);
    const Image rowImage = renderStage(cpu, scene, rowFrame, c.stage).image;
    long unused = 0;
    long differing = triangleMismatches(trianglesOf(cpu, scene, rowFrame), trianglesOf(cpu, scene, frame), unused);
    if (rowImage.width() != cpuImage.width() || rowImage.height() != cpuImage.height()) differing += 1;
    else
      for (int y = 0; y < cpuImage.height(); ++y)
        for (int x = 0; x < cpuImage.width(); ++x) differing += !(rowImage.at(x, y) == cpuImage.at(x, y));
    f.scanlineSame = differing == 0;
    scanline = differing == 0 ? "same" : std::to_string(differing);
  }

  // The depth complexity: the same fragment count at every pixel.
  long countMismatches = 0;
  {
    const auto glCounts = *gl.render(scene, frame, {FrameOutput::FragmentCounts}).fragmentCounts;
    const auto cpuCounts = *cpu.render(scene, frame, {FrameOutput::FragmentCounts}).fragmentCounts;
    for (std::size_t i = 0; i < glCounts.size(); ++i) countMismatches += glCounts[i] != cpuCounts[i];
  }

  f.sameTriangle = mismatches == 0;
  f.countsEqual = countMismatches == 0;
  f.pass = mismatches == 0 && covered > 0 && d.status != DiffStatus::Fail && goldenOk && f.scanlineSame.value_or(true) && countMismatches == 0 &&
           dataMismatches == 0;
  std::string remark;
  if (covered == 0) remark = " (nothing drawn)";
  else if (countMismatches) remark = " (fragment counts differ at " + std::to_string(countMismatches) + " pixels)";
  else if (dataMismatches) remark = " (" + stageName(c.stage) + ": " + std::to_string(dataMismatches) + " values differ in their bits)";
  else if (c.stage.kind == StageKind::Depth || c.stage.kind == StageKind::ShadowMap || c.stage.kind == StageKind::Normals)
    remark = " (stage " + stageName(c.stage) + ", its data bit for bit)";
  else if (c.stage.kind != StageKind::Image) remark = " (stage " + stageName(c.stage) + ")";
  else if (c.allow) remark = " (allowed: " + c.allow->reason + ")";
  const std::string size = std::to_string(cpuImage.width()) + "x" + std::to_string(cpuImage.height());
  f.row = formatted("%-34s %9s %9ld %9lld %5d %7s %8s %4.0f/%-4.0f %s%s", c.name.c_str(), size.c_str(), mismatches,
                    static_cast<long long>(d.differingPixels), d.maxDifference, goldenVerdict.c_str(), scanline.c_str(), msGl, msCpu,
                    f.pass ? "pass" : "FAIL", remark.c_str());
  writeFigures(folders.out, c.name, f);
  return f;
}

// The table of every case that left its figures (unless the run printed
// its lines as it went), the totals (bit-identical cases out of N, the
// worst pixel) and the HTML report in OUT/report, from the figures and the
// PNGs the cases wrote. The cases' verdicts are their own entries' to
// report; this fails only when it cannot write the report.
void summarize(const std::vector<Case>& cases, const Folders& folders, bool printRows) {
  int passed = 0, failed = 0, run = 0, identical = 0, coverageIdentical = 0, scanlineCases = 0, scanlineEqual = 0, countsEqual = 0;
  std::string worstName = "-", glDescription = "-", cpuDescription = "-";
  DiffResult worst;
  std::vector<std::string> notRun;
  std::vector<ReportCase> report;
  ReportFolder reportFolder((fs::path(folders.out) / "report").string());
  bool headed = false;
  for (const Case& c : cases) {
    const std::optional<Figures> f = readFigures(folders.out, c.name);
    if (!f) {
      notRun.push_back(c.name);
      continue;
    }
    if (printRows && !headed) printHeader(f->gl, f->cpu);
    headed = true;
    glDescription = f->gl;
    cpuDescription = f->cpu;
    if (printRows) std::printf("%s\n", f->row.c_str());
    ++run;
    (f->pass ? passed : failed) += 1;
    coverageIdentical += f->sameTriangle ? 1 : 0;
    countsEqual += f->countsEqual ? 1 : 0;
    scanlineCases += f->scanlineSame ? 1 : 0;
    scanlineEqual += f->scanlineSame.value_or(false) ? 1 : 0;
    const DiffThresholds thresholds = thresholdsOf(c);
    const ComparedFiles pair = compareFiles(c.name, (fs::path(folders.out) / "cpu" / (c.name + ".png")).string(),
                                            (fs::path(folders.out) / "gl" / (c.name + ".png")).string(), thresholds);
    if (const std::optional<DiffResult>& d = pair.diffCase.result) {
      identical += d->differingPixels == 0 ? 1 : 0;
      if (d->maxDifference > worst.maxDifference || (worstName == "-" && d->differingPixels > 0)) {
        worstName = c.name;
        worst = *d;
      }
    }
    report.push_back(reportFolder.writeImages(static_cast<int>(report.size()), pair, thresholds));
  }
  ReportContext reportContext;
  reportContext.expectedSource = "CPU (" + cpuDescription + ")";
  reportContext.actualSource = "OpenGL (" + glDescription + ")";
  reportContext.thresholds = backendAgreement();
  const std::string page = reportFolder.finish(report, reportContext);

  std::printf("\ncases: %d; bit-identical: %d of %d; same triangle at every pixel: %d of %d\n", run, identical, run, coverageIdentical, run);
  if (!notRun.empty())
    std::printf("not run: %zu of %zu cases left no figures (their entries did not run, or ended early), the first %s\n", notRun.size(),
                cases.size(), notRun.front().c_str());
  std::printf("depth complexity: the same fragment count at every pixel in %d of %d cases\n", countsEqual, run);
  std::printf("scanline z-buffer (CPU) against the z-buffer: the same triangle and bytes at every pixel in %d of %d cases\n", scanlineEqual,
              scanlineCases);
  if (worst.differingPixels == 0) {
    std::printf("worst pixel: none differs (max difference 0 levels in every case)\n");
  } else {
    std::printf("worst pixel: %d levels at (%d, %d) in %s (%s pixels differ there, RMSE %.3f, PSNR %s dB)\n", worst.maxDifference, worst.worst.x,
                worst.height - 1 - worst.worst.y, worstName.c_str(), formatPixels(worst.differingPixels).c_str(), worst.rmse,
                formatNumber(worst.psnr).c_str());
  }
  std::printf("report: %s\n", page.c_str());
  std::printf("%d passed, %d failed\n", passed, failed);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"facet agreement suite: OpenGL (llvmpipe) against the CPU reference, and both against the goldens"};
  std::string casesDir, only, context = "osmesa";
  Folders folders;
  folders.assets = FACET_ASSETS;
  bool summaryOnly = false;
  app.add_option("--cases", casesDir, "folder of case JSON files")->required();
  app.add_option("--case", only, "run this case alone (CASES/NAME.json) and leave its figures for --summary");
  app.add_flag("--summary", summaryOnly, "render nothing: the table, totals and report from the figures the cases left in --out");
  app.add_option("--golden", folders.golden, "folder of golden PNGs (CPU renders)")->required();
  app.add_option("--out", folders.out, "folder for renders and the HTML report")->required();
  app.add_option("--assets", folders.assets, "the folder assets: scenes are read from");
  app.add_option("--context", context, "osmesa or egl")->check(CLI::IsMember({"osmesa", "egl"}));
  app.add_flag("--update-goldens", folders.update, "write the CPU renders as the new goldens instead of comparing with them");
  CLI11_PARSE(app, argc, argv);

  try {
    std::vector<fs::path> files;
    if (!only.empty()) {
      files.push_back(fs::path(casesDir) / (only + ".json"));
      if (!fs::exists(files.back())) throw Error(files.back().string() + ": no such case");
    } else {
      for (const auto& entry : fs::directory_iterator(casesDir))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
      std::sort(files.begin(), files.end());
      if (files.empty()) throw Error(casesDir + ": no case files");
    }
    std::vector<Case> cases;
    for (const fs::path& file : files) cases.push_back(readCase(file));  // every case file is checked before anything renders
    if (summaryOnly) {
      summarize(cases, folders, true);
      return 0;
    }
    for (const char* folder : {"gl", "cpu", "figures"}) fs::create_directories(fs::path(folders.out) / folder);
    fs::create_directories(folders.golden);

    auto gl = makeGlRenderer(context == "egl" ? GlContextKind::Egl : GlContextKind::OsMesa);
    auto cpu = makeCpuRenderer(0);
    printHeader(gl->description(), cpu->description());
    int failed = 0;
    for (Case& c : cases) {
      const Figures f = runCase(c, *gl, *cpu, folders);
      std::printf("%s\n", f.row.c_str());
      std::fflush(stdout);
      failed += f.pass ? 0 : 1;
    }
    if (only.empty()) summarize(cases, folders, false);
    return failed == 0 ? 0 : 1;
  } catch (const Error& e) {
    std::fprintf(stderr, "facet_agreement: %s\n", e.what());
    return 2;
  }
}
