// facet diff: two PNGs, or two folders of PNGs paired by name, compared
// pixel by pixel with OpenImageIO idiff's thresholds and exit codes.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "command_line.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "common/quote.h"
#include "compare/backend_agreement.h"
#include "compare/compare_files.h"
#include "compare/diff_report_folder.h"
#include "compare/diff_text.h"
#include "compare/folder_pairs.h"
#include "compare/heat_map.h"
#include "image/png.h"
#include "output_option.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

struct DiffOptions {
  std::string expected;
  std::string actual;
  std::string output;  // a .png: heat map; anything else: report folder
  DiffThresholds thresholds;
  bool agreement = false;        // --agreement: backendAgreement() instead of the thresholds
  bool quiet = false;            // -q: nothing on stdout
  bool onlyIfDifferent = false;  // -od: no heat map of equal images
};

constexpr const char* kFooter = R"(
Thresholds are fractions of full scale, as in idiff: 1/255 = 0.0039216 is one
8-bit step; write a fraction as N/255 if you like. A pixel is over a
threshold when any of its R, G, B, A channels differs by more than it.
  PASS     --allowfailures N is set and at most N pixels are over --fail
  FAILURE  otherwise, more than --failpercent % of pixels over --fail, or
           any channel over --hardfail
  WARNING  not a failure, and the same with --warn, --warnpercent, --hardwarn
  PASS     none of these
The defaults are idiff's: --fail 1e-06 --warn 1e-06, percents 0, hard limits
and --allowfailures off, so any difference at all fails. One 8-bit step
(rounding) passes with --fail 1/255, and warns unless --warn 1/255 too.
--agreement holds the images to what facet's backends are held to: every
byte equal (--fail 0).
idiff's one-dash spellings work too: -fail 0.004, -failpercent 1, -warn,
-warnpercent, -hardfail, -hardwarn, -allowfailures, -od, -abs, -q, -v, -a.

The figures are idiff's: mean error, RMS error and PSNR over the channels
the files store (R, G, B and A; a grey file Y), max error and where it is
first met, in fractions of full scale; counts of pixels over --fail and
--warn. Positions are (x, y) from the top-left pixel, as idiff and image
viewers give them. Where facet diff and idiff part (see docs/diff.md):
  - idiff compares 32-bit floats: at a threshold of exactly N/255 a
    difference of N levels counts as over it for some values and not for
    others; here it never does.
  - a translucent pixel: idiff premultiplies R, G, B by alpha when it reads
    a PNG, facet compares the stored values.
  - a file without alpha is opaque here; idiff takes its alpha for 0.
  - 16-bit PNGs are compared at 8 bits (their high byte).
  - with no pixel over --fail idiff passes, never warning, unless given
    -allowfailures; facet warns by --warn as idiff's help says.
  - images of different sizes: exit code 3 here; idiff compares them over
    the larger frame, the missing pixels black and transparent.

With two folders, the PNG files are paired by name; a file in only one
folder is a failure for its case.

-o FILE.png writes a heat map of two PNGs: black where they are equal, dark
purple to crimson where they differ within --fail, orange to pale yellow
where they fail. -o FOLDER writes FOLDER/index.html, one page with the
expected, actual and heat-map images of every case, worst first, and the
images beside it under FOLDER/images. FOLDER is new, empty, or an older
report (it holds the facet-report.txt file facet writes in each); any other
folder is left as it is.

Exit codes (idiff's; with folders, the worst over all cases):
  0  PASS: within the warn thresholds
  1  WARNING: over the warn thresholds, within the fail thresholds
  2  FAILURE: over the fail thresholds, or a file with no partner
  3  the images have different sizes and cannot be compared
  4  file error: missing, unreadable or not a PNG, or -o cannot be written
as every facet command, and never a verdict on the images:
  64 the command line is wrong (an unknown option, a value that does not parse)
  70 internal error, or out of memory)";

// Accepts "0.004", "inf" and "N/255" (any "A/B"; never negative, never NaN:
// "inf/inf" is refused too), rewritten as one decimal number for CLI11 to
// parse, with every digit kept so that 2/255 stays exactly two steps.
CLI::Validator fractionOfFullScale() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto parse = [](const std::string& part, double& value) {
          char* end = nullptr;
          value = std::strtod(part.c_str(), &end);
          return !part.empty() && *end == '\0' && !std::isnan(value);
        };
        const auto slash = text.find('/');
        double a = 0.0, b = 1.0;
        const bool ok = slash == std::string::npos ? parse(text, a)
                                                   : parse(text.substr(0, slash), a) && parse(text.substr(slash + 1), b) && b > 0.0;
        if (!ok || std::isnan(a / b)) return quoteInput(text) + ": expected a number such as 0.004, or a fraction such as 1/255";
        if (a / b < 0.0) return quoteInput(text) + ": a threshold cannot be negative";
        char exact[40];
        std::snprintf(exact, sizeof exact, "%.17g", a / b);
        text = exact;
        return {};
      },
      "FRACTION");
}

// A percent of pixels, 0 to 100. Not CLI::Range: every comparison with NaN
// is false, so Range(0.0, 100.0) lets "nan" through.
CLI::Validator percentOfPixels() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !(value >= 0.0 && value <= 100.0))
          return quoteInput(text) + ": expected a percent of pixels from 0 to 100";
        char exact[40];
        std::snprintf(exact, sizeof exact, "%.17g", value);
        text = exact;
        return {};
      },
      "PERCENT");
}

bool isPngName(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png";
}

// Prints one case, remembers it, and (with a report folder) writes its images.
struct DiffRun {
  const DiffOptions& options;
  std::optional<ReportFolder> report;  // empty: no report
  std::vector<DiffCase> cases;
  std::vector<ReportCase> reportCases;

  void say(const std::string& text) const {
    if (!options.quiet) std::fputs(text.c_str(), stdout);
  }

  void add(const ComparedFiles& compared) {
    say(caseText(compared.diffCase, options.thresholds));
    if (report) reportCases.push_back(report->writeImages(static_cast<int>(cases.size()) + 1, compared, options.thresholds));
    cases.push_back(compared.diffCase);
  }

  int finish() {
    if (report) {
      const std::string page = report->finish(reportCases, {options.expected, options.actual, options.thresholds});
      say("report written to " + page + "\n");
    }
    say(summaryLine(cases) + "\n");
    return static_cast<int>(worstVerdict(cases));
  }
};

int compareTwoFiles(const DiffOptions& options) {
  const bool heatMapOnly = !options.output.empty() && isPngName(options.output);
  // The output checked before any image is read: a run never ends unable to write what it made.
  if (heatMapOnly) checkOutputFile(options.output, {options.expected, options.actual}, MissingFolders::Created);
  else if (!options.output.empty()) checkReportFolder(options.output, {options.expected, options.actual});
  const std::string name = fs::path(options.expected).filename().string();
  const ComparedFiles compared = compareFiles(name, options.expected, options.actual, options.thresholds);
  const DiffCase& c = compared.diffCase;
  if (!c.result) {  // nothing to show: the one line on stderr, as every facet error
    std::fprintf(stderr, "facet: %s\n", c.problem.c_str());
    return static_cast<int>(c.verdict);
  }
  DiffRun run{options, {}, {}, {}};
  if (!heatMapOnly && !options.output.empty()) run.report.emplace(options.output);
  run.add(compared);
  if (heatMapOnly && options.onlyIfDifferent && c.result->differingPixels == 0) {
    run.say("heat map not written: the images are equal (-od)\n");
  } else if (heatMapOnly) {
    const fs::path folder = fs::path(options.output).parent_path();
    std::error_code ec;
    if (!folder.empty()) fs::create_directories(folder, ec);  // a failure shows when writing
    writePng(options.output, heatMap(compared.expected, compared.actual, options.thresholds));
    run.say("heat map written to " + options.output + "\n");
  }
  return run.finish();
}

int compareTwoFolders(const DiffOptions& options) {
  if (isPngName(options.output))
    throw Error("-o " + options.output + ": two folders make a report folder (index.html and images), not one PNG");
  if (options.onlyIfDifferent && !options.output.empty())
    throw UsageError("-od: applies to the heat map of two PNGs; a report folder is written whatever the folders hold");
  if (!options.output.empty()) checkReportFolder(options.output, {options.expected, options.actual});
  const std::vector<FilePair> pairs = pairFolderFiles(options.expected, options.actual);
  if (pairs.empty()) throw Error(options.expected + " and " + options.actual + ": no PNG files in either folder");
  DiffRun run{options, {}, {}, {}};
  if (!options.output.empty()) run.report.emplace(options.output);
  for (const FilePair& pair : pairs) run.add(compareFiles(pair.name, pair.expectedPath, pair.actualPath, options.thresholds));
  return run.finish();
}

int runDiff(DiffOptions options) {
  if (options.agreement) options.thresholds = backendAgreement();
  checkThresholds(options.thresholds);
  std::error_code ec;
  const bool expectedIsFolder = fs::is_directory(options.expected, ec);
  const bool actualIsFolder = fs::is_directory(options.actual, ec);
  if (expectedIsFolder && actualIsFolder) return compareTwoFolders(options);
  if (expectedIsFolder != actualIsFolder)
    throw Error((expectedIsFolder ? options.expected : options.actual) + ": is a folder, but " +
                (expectedIsFolder ? options.actual : options.expected) + " is not; give two PNG files or two folders");
  return compareTwoFiles(options);
}

// idiff's options that change nothing here, accepted so that an idiff
// command line runs as it is, and those facet diff does not take, refused
// with the reason rather than as unknown.
void addIdiffOnlyOptions(CLI::App& command) {
  const char* accepted = "idiff options that change nothing here";
  command.add_flag("-v")->description("idiff's verbose report: facet diff always prints the figures")->group(accepted);
  command.add_flag("-a")->description("idiff's every subimage and MIP level: a PNG holds one image")->group(accepted);
  command.add_flag("--abs")->description("idiff's absolute difference image: the heat map shows absolute differences")->group(accepted);

  const char* refused = "idiff options refused here";
  const auto refuse = [&](const std::string& name, const std::string& reason, bool takesValue) {
    const auto fail = [name, reason](const auto&...) { throw CLI::ValidationError(name, reason); };
    CLI::Option* option = takesValue ? command.add_option_function<std::string>(name, fail, reason) : command.add_flag_callback(name, fail, reason);
    option->group(refused);
  };
  refuse("-p", "no perceptual comparison: facet diff compares channel values (idiff's -p is Yee's perceptual metric)", false);
  const std::string relative =
      "no relative thresholds: they suit high-dynamic-range images, and an 8-bit PNG is already encoded for the eye (sRGB); use --fail and --warn";
  refuse("--failrelative", relative, true);
  refuse("--warnrelative", relative, true);
  refuse("--scale", "no scale factor: it scales idiff's difference image; facet's heat map (-o) colours each difference by its level and --fail",
         true);
}

}  // namespace

Command addDiffCommand(CLI::App& app) {
  auto options = std::make_shared<DiffOptions>();
  CLI::App* command = app.add_subcommand("diff", "Compare two PNGs, or two folders of PNGs, pixel by pixel (exit codes as OpenImageIO's idiff)");
  command->add_option("expected", options->expected, "the expected PNG, or a folder of them")->required();
  command->add_option("actual", options->actual, "the actual PNG, or a folder of them")->required();
  DiffThresholds& t = options->thresholds;
  const auto threshold = [&](const char* flag, double& value, const char* help) {
    command->add_option(flag, value, help)->transform(fractionOfFullScale())->capture_default_str();
  };
  threshold("--fail", t.failThreshold, "a channel difference above this fails its pixel (fraction of full scale)");
  command->add_option("--failpercent", t.failPercent, "percent of pixels allowed to fail")->transform(percentOfPixels())->capture_default_str();
  threshold("--hardfail", t.hardFail, "any channel difference above this fails the comparison (default: off)");
  command->add_option("--allowfailures", t.allowFailures, "pass when at most this many pixels fail, by any amount (default: off)")
      ->check(wholeNumberIn(0, std::numeric_limits<int>::max()))
      ->capture_default_str();
  threshold("--warn", t.warnThreshold, "a channel difference above this warns for its pixel (fraction of full scale)");
  command->add_option("--warnpercent", t.warnPercent, "percent of pixels allowed to warn")->transform(percentOfPixels())->capture_default_str();
  threshold("--hardwarn", t.hardWarn, "any channel difference above this warns (default: off)");
  command->add_flag("--agreement", options->agreement,
                    "hold the images to what the OpenGL and CPU backends are held to: every byte equal (overrides the thresholds)");
  refuseEmptyName(command->add_option("-o,--output", options->output, "FILE.png: heat map (two PNGs only); FOLDER: HTML report with images"));
  command->add_flag("--od", options->onlyIfDifferent, "write the heat map only when the images differ");
  command->add_flag("-q,--quiet", options->quiet, "print nothing: the exit code is the verdict (problems still go to stderr)");
  addIdiffOnlyOptions(*command);
  command->footer(kFooter);
  return [options]() {
    // Every problem here is about a file (or the output): idiff's exit code 4,
    // not the 1 that main gives other facet errors (1 means WARNING here).
    // The command line (64) and internal errors (70) go on to main, whose
    // codes no verdict uses.
    try {
      return runDiff(*options);
    } catch (const UsageError&) {
      throw;
    } catch (const OutOfMemory&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw OutOfMemory("comparing " + options->expected + " with " + options->actual);
    } catch (const Error& e) {
      std::fprintf(stderr, "facet: %s\n", e.what());
    } catch (const fs::filesystem_error& e) {
      std::fprintf(stderr, "facet: %s\n", e.what());
    }
    return static_cast<int>(Verdict::FileError);
  };
}

}  // namespace facet
