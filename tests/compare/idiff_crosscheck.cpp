// `facet diff` against OpenImageIO's idiff (Debian openimageio-tools) on
// pairs of PNGs written here: the same verdict (exit code), the same counts
// of pixels over -fail and over -warn, and the same mean error, RMS error,
// PSNR and max error (and its position and channel, where one channel alone
// holds the largest difference), to the six digits idiff prints. Both get
// the same command line, in idiff's spelling, with idiff's -v so that it
// always prints its figures.
//
// Where facet diff parts from idiff on purpose (docs/diff.md), a case says
// so and checks that the difference is the one documented.
//
//   idiff_crosscheck FACET WORK_FOLDER
// Exit 0: all agree; 1: a difference (each printed); 77: no idiff on PATH
// (ctest reports the test as skipped).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "image/png_bytes.h"

namespace fs = std::filesystem;

namespace {

// ---- images -----------------------------------------------------------------

enum class Layout { Grey = 0, GreyAlpha = 4, Rgb = 2, Rgba = 6 };  // the PNG colour type

int channelsOf(Layout layout) {
  switch (layout) {
    case Layout::Grey: return 1;
    case Layout::GreyAlpha: return 2;
    case Layout::Rgb: return 3;
    case Layout::Rgba: return 4;
  }
  return 0;
}

// Samples as the file stores them, rows from the top.
struct Picture {
  int width = 0, height = 0;
  Layout layout = Layout::Rgba;
  std::vector<int> samples;  // width x height x channelsOf(layout), 0..255

  int channels() const { return channelsOf(layout); }
  int& at(int x, int y, int c) { return samples[static_cast<std::size_t>((y * width + x) * channels() + c)]; }
  int at(int x, int y, int c) const { return samples[static_cast<std::size_t>((y * width + x) * channels() + c)]; }
  bool hasAlpha() const { return layout == Layout::GreyAlpha || layout == Layout::Rgba; }
};

Picture filled(int width, int height, Layout layout, int value, int alpha = 255) {
  Picture p{width, height, layout, std::vector<int>(static_cast<std::size_t>(width * height * channelsOf(layout)), value)};
  if (p.hasAlpha())
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) p.at(x, y, p.channels() - 1) = alpha;
  return p;
}

Picture randomPicture(int width, int height, Layout layout, std::mt19937& random, bool randomAlpha = false) {
  Picture p = filled(width, height, layout, 0);
  std::uniform_int_distribution<int> level(0, 255);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < p.channels(); ++c)
        if (!p.hasAlpha() || c < p.channels() - 1 || randomAlpha) p.at(x, y, c) = level(random);
  return p;
}

// Every colour sample moved by up to `amplitude` levels either way (clamped).
Picture withNoise(Picture p, int amplitude, std::mt19937& random) {
  std::uniform_int_distribution<int> step(-amplitude, amplitude);
  const int colours = p.hasAlpha() ? p.channels() - 1 : p.channels();
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x)
      for (int c = 0; c < colours; ++c) p.at(x, y, c) = std::clamp(p.at(x, y, c) + step(random), 0, 255);
  return p;
}

// How idiff's OpenImageIO premultiplies a PNG's colours by its alpha as it
// reads it, which changed with 2.5 (Debian 13): the files here carry no gAMA
// or sRGB chunk, which 2.5 takes for sRGB and premultiplies in linear light.
enum class Premultiply {
  Stored,       // 2.4: each colour sample times alpha / 255, rounded down (png_associateAlpha, gamma 1)
  LinearLight,  // 2.5: sRGB decoded to linear, times alpha, encoded again, rounded to the nearest level
};

float srgbToLinear(float v) { return v <= 0.04045f ? v * (1.0f / 12.92f) : std::pow((v + 0.055f) * (1.0f / 1.055f), 2.4f); }
float linearToSrgb(float v) { return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f; }

Picture premultiplied(Picture p, Premultiply how) {
  if (!p.hasAlpha()) return p;
  const int alpha = p.channels() - 1;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const int a = p.at(x, y, alpha);
      for (int c = 0; c < alpha; ++c) {
        int& v = p.at(x, y, c);
        if (how == Premultiply::Stored) {
          v = v * a / 255;
        } else if (a != 255) {
          const float f = linearToSrgb(srgbToLinear(static_cast<float>(v) * (1.0f / 255.0f)) * (static_cast<float>(a) * (1.0f / 255.0f)));
          v = static_cast<int>(std::clamp(f * 255.0f + 0.5f, 0.0f, 255.0f));
        }
      }
    }
  return p;
}

void writePng(const fs::path& path, const Picture& p) {
  std::string raw;
  for (int y = 0; y < p.height; ++y) {
    raw += '\0';  // filter: none
    for (int x = 0; x < p.width; ++x)
      for (int c = 0; c < p.channels(); ++c) raw += static_cast<char>(p.at(x, y, c));
  }
  using namespace facet::test;
  const std::string chunks = ihdrChunk(static_cast<std::uint32_t>(p.width), static_cast<std::uint32_t>(p.height), 8, static_cast<int>(p.layout)) +
                             pngChunk("IDAT", zlibStored(raw));
  std::ofstream(path, std::ios::binary) << pngFile(chunks);
}

// The largest channel difference, and whether one channel of one pixel
// alone holds it (idiff's position is then the only one possible: float
// rounding cannot reorder differences a whole level apart).
struct Largest {
  int levels = 0;
  int holders = 0;
};

Largest largestDifference(const Picture& a, const Picture& b) {
  Largest largest;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    const int d = std::abs(a.samples[i] - b.samples[i]);
    if (d > largest.levels) largest = {d, 1};
    else if (d == largest.levels && d > 0) ++largest.holders;
  }
  return largest;
}

// ---- running the two programs ----------------------------------------------

struct Output {
  int exitCode = -1;
  std::string text;  // stdout and stderr
};

Output run(const std::vector<std::string>& args) {
  int pipeEnds[2];
  if (::pipe(pipeEnds) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    ::dup2(pipeEnds[1], 1);
    ::dup2(pipeEnds[1], 2);
    ::close(pipeEnds[0]);
    ::close(pipeEnds[1]);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(pipeEnds[1]);
  Output out;
  char buffer[4096];
  for (ssize_t n; (n = ::read(pipeEnds[0], buffer, sizeof buffer)) > 0;) out.text.append(buffer, static_cast<std::size_t>(n));
  ::close(pipeEnds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  out.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
  return out;
}

std::optional<std::string> findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path ? path : "/usr/bin");
  for (std::string folder; std::getline(folders, folder, ':');) {
    const fs::path candidate = fs::path(folder.empty() ? "." : folder) / program;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return std::nullopt;
}

// ---- what each prints ---------------------------------------------------------

struct Figures {
  int exitCode = -1;
  long overFail = -1, overWarn = -1;
  double mean = NAN, rms = NAN, psnr = NAN, maxError = NAN;
  std::string where;  // "(x, y) C", empty when the images are equal
};

double number(const std::string& text) { return text == "inf" ? std::numeric_limits<double>::infinity() : std::stod(text); }

std::string capture(const std::string& text, const std::string& pattern) {
  std::smatch m;
  return std::regex_search(text, m, std::regex(pattern)) ? m[1].str() : std::string();
}

// idiff -v: "  Mean error = ...", "  RMS error = ...", "  Peak SNR = ...",
// "  Max error  = V @ (x, y, C)  values are ...", then the pixels over the
// warn threshold and the pixels over the fail threshold.
Figures parseIdiff(const Output& out) {
  Figures f;
  f.exitCode = out.exitCode;
  f.mean = number(capture(out.text, R"(Mean error = (\S+))"));
  f.rms = number(capture(out.text, R"(RMS error = (\S+))"));
  f.psnr = number(capture(out.text, R"(Peak SNR = (\S+))"));
  f.maxError = number(capture(out.text, R"(Max error  = (\S+))"));
  std::smatch m;
  if (std::regex_search(out.text, m, std::regex(R"(@ \((\d+), (\d+), (\w+)\))"))) {
    std::ostringstream where;
    where << "(" << m[1] << ", " << m[2] << ") " << m[3];
    f.where = where.str();
  }
  const std::regex over(R"(\n  (\d+) pixels \([^)]*\) over )");
  std::vector<long> counts;
  for (auto it = std::sregex_iterator(out.text.begin(), out.text.end(), over); it != std::sregex_iterator(); ++it) counts.push_back(std::stol((*it)[1]));
  if (counts.size() == 2) {
    f.overWarn = counts[0];
    f.overFail = counts[1];
  }
  return f;
}

// facet diff: "  mean error M, RMS error R, PSNR P dB", "  max error V (N
// levels) at (x, y) C: ...", "  over fail threshold T: N pixels (...",
// "  over warn threshold T: N pixels (...".
Figures parseFacet(const Output& out) {
  Figures f;
  f.exitCode = out.exitCode;
  f.mean = number(capture(out.text, R"(mean error (\S+),)"));
  f.rms = number(capture(out.text, R"(RMS error (\S+),)"));
  f.psnr = number(capture(out.text, R"(PSNR (\S+) dB)"));
  f.maxError = number(capture(out.text, R"(max error (\S+))"));
  f.where = capture(out.text, R"(max error \S+ \(\d+ levels?\) at (\(\d+, \d+\) \w+):)");
  f.overFail = std::stol(capture(out.text, R"(over fail threshold [^:]*: (\d+) pixel)"));
  f.overWarn = std::stol(capture(out.text, R"(over warn threshold [^:]*: (\d+) pixel)"));
  return f;
}

// How far idiff's own figures stray: it turns each 8-bit value into a
// 32-bit float (v * (1/255.0f), within a float step of v/255, 2^-24 at most
// below 1) and subtracts two of them, so each difference it sums, or keeps
// as the max error, is within 2^-23 of the exact one; and so are its mean
// and RMS error, the mean and root-mean-square of those differences. facet
// sums whole levels, exactly. PSNR = -20 log10(RMS) strays by 20/ln(10) x
// that over the RMS.
constexpr double kIdiffFloatSlack = 0x1p-23;

double psnrSlack(double rms) { return rms > 0.0 ? 20.0 / std::log(10.0) * kIdiffFloatSlack / rms : 0.0; }

// Equal to what both print, six significant digits ("%g"): apart by at most
// `slack` plus one unit of the sixth digit (each side rounds to it).
bool samePrinted(double a, double b, double slack = 0.0) {
  if (std::isinf(a) || std::isinf(b)) return a == b;
  if (std::isnan(a) || std::isnan(b)) return false;
  const double size = std::max(std::abs(a), std::abs(b));
  if (size == 0.0) return true;
  const double unit = std::pow(10.0, std::floor(std::log10(size)) - 5.0);
  return std::abs(a - b) <= slack + unit;
}

// ---- the cases ---------------------------------------------------------------

// What facet diff gives where it parts from idiff on purpose. Every case
// also allows one: where at most -allowfailures pixels (default 0) are over
// -fail, idiff (2.4, 2.5) passes without looking at the warn thresholds and the
// hard limits; facet applies them (its own rule is held by the unit tests).
enum class Expect {
  Same,                   // every figure and the verdict
  WarnsWhereIdiffPasses,  // Same, and the case must be one where facet warns and idiff passes
  PremultipliedSame,      // the figures facet gives for the premultiplied pair are idiff's for the stored pair
  DifferentSize,          // facet: exit 3; idiff pads the smaller image and compares
  MissingAlphaOpaque,     // RGB against RGBA of opaque pixels: equal for facet, alpha 0 against 255 for idiff
};

struct Case {
  std::string name;
  Picture expected, actual;
  std::vector<std::string> args;  // idiff's spelling, given to both
  Expect expect = Expect::Same;
};

std::vector<Case> makeCases() {
  std::mt19937 random(20240611);
  std::vector<Case> cases;
  const auto add = [&](std::string name, Picture e, Picture a, std::vector<std::string> args = {}, Expect expect = Expect::Same) {
    cases.push_back({std::move(name), std::move(e), std::move(a), std::move(args), expect});
  };

  const Picture base = randomPicture(16, 12, Layout::Rgba, random);
  add("identical", base, base);

  Picture oneLevel = base;
  oneLevel.at(5, 3, 0) = oneLevel.at(5, 3, 0) == 255 ? 254 : oneLevel.at(5, 3, 0) + 1;
  add("one_level_red", base, oneLevel);
  add("one_level_red_passes_with_fail_0.005", base, oneLevel, {"-fail", "0.005", "-warn", "0.005"});

  const Picture rgb = randomPicture(15, 9, Layout::Rgb, random);
  Picture rgbOneLevel = rgb;
  rgbOneLevel.at(14, 8, 1) = rgbOneLevel.at(14, 8, 1) == 0 ? 1 : rgbOneLevel.at(14, 8, 1) - 1;
  add("rgb_files_one_level_green", rgb, rgbOneLevel);

  // Alpha alone differs, on black pixels: premultiplying changes nothing there.
  Picture clear = filled(10, 10, Layout::Rgba, 0, 255);
  Picture clearer = clear;
  clearer.at(2, 7, 3) = 200;
  clearer.at(9, 0, 3) = 0;
  clearer.at(4, 4, 3) = 254;
  add("alpha_only", clear, clearer);
  add("alpha_only_hardfail", clear, clearer, {"-fail", "0.5", "-failpercent", "10", "-hardfail", "0.3"});

  const Picture grey = randomPicture(20, 6, Layout::Grey, random);
  add("grey_files_noise_3", grey, withNoise(grey, 3, random));
  Picture greyAlpha = randomPicture(7, 7, Layout::GreyAlpha, random);
  Picture greyAlphaChanged = withNoise(greyAlpha, 2, random);
  for (int y = 0; y < 7; ++y) {  // alpha changes only where the grey is 0 (see alpha_only)
    greyAlpha.at(y, y, 0) = greyAlphaChanged.at(y, y, 0) = 0;
    greyAlphaChanged.at(y, y, 1) = 255 - 20 * y;
  }
  add("grey_alpha_files", greyAlpha, greyAlphaChanged);

  // Noise of several amplitudes, several sizes, default and looser thresholds.
  int n = 0;
  for (const int amplitude : {1, 2, 4, 16, 64, 255}) {
    const int width = 9 + 13 * n, height = 5 + 7 * n;
    ++n;
    const Picture image = randomPicture(width, height, Layout::Rgba, random);
    const Picture noisy = withNoise(image, amplitude, random);
    const std::string name = "noise_" + std::to_string(amplitude) + "_" + std::to_string(width) + "x" + std::to_string(height);
    add(name, image, noisy);
    add(name + "_fail_0.02_30pct_warn_0.006", image, noisy, {"-fail", "0.02", "-failpercent", "30", "-warn", "0.006"});
    add(name + "_fail_0.1_60pct_warn_0.05_40pct", image, noisy, {"-fail", "0.1", "-failpercent", "60", "-warn", "0.05", "-warnpercent", "40"});
  }

  // A few pixels far over -fail in an image of one-level noise.
  const Picture plain = randomPicture(20, 20, Layout::Rgba, random);
  Picture spots = withNoise(plain, 1, random);
  const int spotted[3][3] = {{3, 4, 0}, {17, 11, 2}, {8, 19, 1}};  // x, y, channel
  for (const auto& s : spotted) spots.at(s[0], s[1], s[2]) = plain.at(s[0], s[1], s[2]) < 128 ? plain.at(s[0], s[1], s[2]) + 40 + s[0] : 10;
  add("spots_fail", plain, spots, {"-fail", "0.1"});
  add("spots_within_failpercent_warn", plain, spots, {"-fail", "0.1", "-failpercent", "1"});
  add("spots_over_failpercent", plain, spots, {"-fail", "0.1", "-failpercent", "0.5"});
  add("spots_hardfail", plain, spots, {"-fail", "0.1", "-failpercent", "1", "-hardfail", "0.12"});
  add("spots_allowfailures", plain, spots, {"-fail", "0.1", "-allowfailures", "3"});
  add("spots_allowfailures_too_few", plain, spots, {"-fail", "0.1", "-allowfailures", "2"});
  add("spots_hardwarn", plain, spots, {"-fail", "0.1", "-failpercent", "1", "-warn", "0.1", "-warnpercent", "1", "-hardwarn", "0.12"});
  add("spots_pass", plain, spots, {"-fail", "0.1", "-failpercent", "1", "-warn", "0.1", "-warnpercent", "1"});

  // Where facet parts from idiff on purpose.
  add("nothing_over_fail_warns", plain, withNoise(plain, 1, random), {"-fail", "0.1"}, Expect::WarnsWhereIdiffPasses);
  const Picture translucent = randomPicture(12, 8, Layout::Rgba, random, true);
  add("translucent_noise", translucent, withNoise(translucent, 6, random), {}, Expect::PremultipliedSame);
  add("different_sizes", base, randomPicture(16, 13, Layout::Rgba, random), {}, Expect::DifferentSize);
  Picture rgbOfBase = filled(16, 12, Layout::Rgb, 0);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) rgbOfBase.at(x, y, c) = base.at(x, y, c);
  add("rgb_against_opaque_rgba", rgbOfBase, base, {}, Expect::MissingAlphaOpaque);
  return cases;
}

// ---- checking -----------------------------------------------------------------

long allowFailures(const std::vector<std::string>& args) {
  const auto it = std::find(args.begin(), args.end(), "-allowfailures");
  return it != args.end() && it + 1 != args.end() ? std::stol(*(it + 1)) : 0;
}

struct Checker {
  std::vector<std::string> problems;

  void same(const char* what, double facet, double idiff, double slack) {
    if (!samePrinted(facet, idiff, slack)) {
      char line[160];
      std::snprintf(line, sizeof line, "%s: facet %.9g, idiff %.9g (more apart than %.3g)", what, facet, idiff, slack);
      problems.push_back(line);
    }
  }
  void same(const char* what, long facet, long idiff) {
    if (facet != idiff) problems.push_back(std::string(what) + ": facet " + std::to_string(facet) + ", idiff " + std::to_string(idiff));
  }
  void same(const char* what, const std::string& facet, const std::string& idiff) {
    if (facet != idiff) problems.push_back(std::string(what) + ": facet '" + facet + "', idiff '" + idiff + "'");
  }
  void require(bool condition, const std::string& what) {
    if (!condition) problems.push_back(what);
  }

  // The exit codes: equal, unless idiff passed outright (see Expect).
  void verdict(const Figures& facet, const Figures& idiff, long allowFailures) {
    if (facet.overFail >= 0 && facet.overFail <= allowFailures && idiff.exitCode == 0) return;
    same("exit code", static_cast<long>(facet.exitCode), static_cast<long>(idiff.exitCode));
  }

  int positionsCompared = 0;

  void figures(const Figures& facet, const Figures& idiff, const Largest& largest) {
    same("pixels over -fail", facet.overFail, idiff.overFail);
    same("pixels over -warn", facet.overWarn, idiff.overWarn);
    same("mean error", facet.mean, idiff.mean, kIdiffFloatSlack);
    same("RMS error", facet.rms, idiff.rms, kIdiffFloatSlack);
    same("PSNR", facet.psnr, idiff.psnr, psnrSlack(facet.rms));
    same("max error", facet.maxError, idiff.maxError, kIdiffFloatSlack);
    if (largest.holders == 1) {
      same("max error at", facet.where, idiff.where);
      ++positionsCompared;
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: idiff_crosscheck FACET WORK_FOLDER\n");
    return 2;
  }
  const std::optional<std::string> idiff = findOnPath("idiff");
  if (!idiff) {
    std::printf("skipped: no idiff on PATH (Debian package openimageio-tools, see scripts/install-deps.sh)\n");
    return 77;
  }
  // idiff's OpenImageIO, from the second line of its help: "OpenImageIO 2.4.7.1 http://...".
  const std::string version = capture(run({*idiff, "--help"}).text, "OpenImageIO ([0-9]+\\.[0-9]+)");
  if (version.empty()) {
    std::printf("cannot tell idiff's OpenImageIO version from idiff --help\n");
    return 1;
  }
  const int major = std::stoi(version), minor = std::stoi(version.substr(version.find('.') + 1));
  const Premultiply premultiply = major > 2 || (major == 2 && minor >= 5) ? Premultiply::LinearLight : Premultiply::Stored;
  std::printf("idiff of OpenImageIO %s: translucent pixels premultiplied %s\n", version.c_str(),
              premultiply == Premultiply::Stored ? "as stored" : "in linear light");
  const std::string facet = argv[1];
  const fs::path work = argv[2];
  fs::remove_all(work);
  fs::create_directories(work);

  int failures = 0, positionsCompared = 0;
  const std::vector<Case> cases = makeCases();
  for (const Case& c : cases) {
    const std::string e = (work / (c.name + "_expected.png")).string(), a = (work / (c.name + "_actual.png")).string();
    writePng(e, c.expected);
    writePng(a, c.actual);
    std::vector<std::string> idiffArgs = {*idiff, "-v"}, facetArgs = {facet, "diff", "-v"};
    idiffArgs.insert(idiffArgs.end(), c.args.begin(), c.args.end());
    facetArgs.insert(facetArgs.end(), c.args.begin(), c.args.end());
    const Output idiffOut = run([&] { auto v = idiffArgs; v.insert(v.end(), {e, a}); return v; }());
    const Output facetOut = run([&] { auto v = facetArgs; v.insert(v.end(), {e, a}); return v; }());

    Checker check;
    try {
      const Figures i = parseIdiff(idiffOut);
      switch (c.expect) {
        case Expect::Same:
        case Expect::WarnsWhereIdiffPasses: {
          const Figures f = parseFacet(facetOut);
          check.verdict(f, i, allowFailures(c.args));
          check.figures(f, i, largestDifference(c.expected, c.actual));
          if (c.expect == Expect::WarnsWhereIdiffPasses)
            check.require(f.overFail == 0 && f.exitCode == 1 && i.exitCode == 0,
                          "the case should be one where facet warns (1) and idiff passes (0): facet " + std::to_string(f.exitCode) + ", idiff " +
                              std::to_string(i.exitCode));
          break;
        }
        case Expect::PremultipliedSame: {
          const std::string pe = (work / (c.name + "_expected_premultiplied.png")).string();
          const std::string pa = (work / (c.name + "_actual_premultiplied.png")).string();
          const Picture expected = premultiplied(c.expected, premultiply), actual = premultiplied(c.actual, premultiply);
          writePng(pe, expected);
          writePng(pa, actual);
          const Figures stored = parseFacet(facetOut);
          const Figures f = parseFacet(run([&] { auto v = facetArgs; v.insert(v.end(), {pe, pa}); return v; }()));
          check.verdict(f, i, allowFailures(c.args));
          check.figures(f, i, largestDifference(expected, actual));
          check.require(!samePrinted(stored.rms, i.rms, kIdiffFloatSlack), "the stored pair should differ from idiff's figures, or the case tests nothing");
          break;
        }
        case Expect::DifferentSize:
          check.require(facetOut.exitCode == 3, "facet should refuse different sizes with exit code 3, gave " + std::to_string(facetOut.exitCode));
          check.require(i.exitCode == 2 && i.overFail > 0, "idiff compares different sizes (FAILURE), gave " + std::to_string(i.exitCode));
          break;
        case Expect::MissingAlphaOpaque: {
          const Figures f = parseFacet(facetOut);
          check.require(f.exitCode == 0 && f.rms == 0.0, "facet should find the RGB file equal to the opaque RGBA one");
          check.require(i.exitCode == 2 && i.maxError == 1.0, "idiff takes the RGB file's alpha for 0: max error 1, FAILURE");
          break;
        }
      }
    } catch (const std::exception& error) {
      check.problems.push_back(std::string("cannot read the output: ") + error.what());
    }

    std::printf("%-4s %s (%s)\n", check.problems.empty() ? "ok" : "FAIL", c.name.c_str(),
                [&] {
                  std::string args;
                  for (const std::string& arg : c.args) args += (args.empty() ? "" : " ") + arg;
                  return args.empty() ? std::string("defaults") : args;
                }()
                    .c_str());
    positionsCompared += check.positionsCompared;
    if (!check.problems.empty()) {
      ++failures;
      for (const std::string& p : check.problems) std::printf("       %s\n", p.c_str());
      std::printf("  idiff said (exit %d):\n%s  facet diff said (exit %d):\n%s", idiffOut.exitCode, idiffOut.text.c_str(), facetOut.exitCode,
                  facetOut.text.c_str());
    }
  }
  std::printf("%zu cases (max error position compared in %d, where one channel alone holds it), %d with a difference from idiff that is not documented\n",
              cases.size(), positionsCompared, failures);
  return failures == 0 ? 0 : 1;
}
