// Files and folders: pairing by name, verdicts for every way a case can go
// wrong, the worst-first order and the HTML page.
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <doctest/doctest.h>

#include "common/error.h"
#include "compare/compare_files.h"
#include "compare/diff_report_folder.h"
#include "compare/diff_text.h"
#include "compare/folder_pairs.h"
#include "compare/image_diff.h"
#include "image/png.h"
#include "test_images.h"
#include "scratch_folder.h"

using namespace facet;
using namespace facet::test;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return scratchFolder("compare", name); }

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

std::size_t positionOf(const std::string& html, const std::string& name) {
  const std::size_t at = html.find("data-name=\"" + name + "\"");
  REQUIRE_MESSAGE(at != std::string::npos, name);
  return at;
}

}  // namespace

TEST_CASE("compareFiles turns every problem into a verdict naming the file") {
  const fs::path dir = scratch("files");
  const std::string a = (dir / "a.png").string(), wide = (dir / "wide.png").string(), text = (dir / "text.png").string();
  writePng(a, Image(10, 10, kSlate));
  writePng(wide, Image(12, 10, kSlate));
  writeText(text, "not a png");
  const DiffThresholds t;

  const ComparedFiles same = compareFiles("a.png", a, a, t);
  CHECK(same.diffCase.verdict == Verdict::Pass);
  CHECK(same.diffCase.result.has_value());

  const DiffCase sizes = compareFiles("a.png", a, wide, t).diffCase;
  CHECK(sizes.verdict == Verdict::DifferentSize);
  CHECK(sizes.problem == "images of different sizes: " + a + " is 10x10, " + wide + " is 12x10");

  const DiffCase unreadable = compareFiles("a.png", a, text, t).diffCase;
  CHECK(unreadable.verdict == Verdict::FileError);
  CHECK(unreadable.problem == text + ": not a PNG file");

  const DiffCase missing = compareFiles("a.png", a, (dir / "none.png").string(), t).diffCase;
  CHECK(missing.verdict == Verdict::FileError);
  CHECK(missing.problem == (dir / "none.png").string() + ": no such file");

  const ComparedFiles alone = compareFiles("a.png", a, "", t);
  CHECK(alone.diffCase.verdict == Verdict::Fail);
  CHECK(alone.diffCase.problem == a + ": no actual image to compare it with");
  CHECK(alone.expected.width() == 10);  // still there for the report
  fs::remove_all(dir);
}

TEST_CASE("folders pair their PNG files by name and ignore everything else") {
  const fs::path dir = scratch("pairs");
  fs::create_directories(dir / "e" / "sub.png");
  fs::create_directories(dir / "a");
  for (const char* name : {"both.png", "only_e.PNG", "readme.txt"}) writeText(dir / "e" / name, "");
  for (const char* name : {"both.png", "only_a.png"}) writeText(dir / "a" / name, "");
  const std::vector<FilePair> pairs = pairFolderFiles((dir / "e").string(), (dir / "a").string());
  REQUIRE(pairs.size() == 3);
  CHECK(pairs[0].name == "both.png");
  CHECK(pairs[0].expectedPath == (dir / "e" / "both.png").string());
  CHECK(pairs[0].actualPath == (dir / "a" / "both.png").string());
  CHECK(pairs[1].name == "only_a.png");
  CHECK(pairs[1].expectedPath.empty());
  CHECK(pairs[2].name == "only_e.PNG");
  CHECK(pairs[2].actualPath.empty());
  CHECK_THROWS_WITH_AS(pairFolderFiles((dir / "nowhere").string(), (dir / "a").string()), doctest::Contains("cannot read the folder"), Error);
  fs::remove_all(dir);
}

TEST_CASE("the report folder holds every image and a page that lists the cases worst first") {
  const fs::path dir = scratch("report");
  const Image base(10, 10, kSlate);
  const DiffThresholds t;
  const std::vector<ComparedFiles> compared = {
      // In name order, as `facet diff` meets them.
      {DiffCase{"a<b>.png", "e/a<b>.png", "a/a<b>.png", Verdict::Pass, "", compareImages(base, base, t)}, base, base},
      {DiffCase{"edge.png", "e/edge.png", "a/edge.png", Verdict::Fail, "",
                compareImages(objectImage(10, 10, 2, 5), objectImage(10, 10, 2, 6), t)},
       objectImage(10, 10, 2, 5), objectImage(10, 10, 2, 6)},
      {DiffCase{"off_by_one.png", "e/off_by_one.png", "a/off_by_one.png", Verdict::Warn, "",
                compareImages(base, withPixel(base, 1, 1, {11, 20, 40, 255}), t)},
       base, withPixel(base, 1, 1, {11, 20, 40, 255})},
      {DiffCase{"one_pixel.png", "e/one_pixel.png", "a/one_pixel.png", Verdict::Fail, "",
                compareImages(base, withPixel(base, 1, 1, {20, 20, 40, 255}), t)},
       base, withPixel(base, 1, 1, {20, 20, 40, 255})},
      {DiffCase{"only.png", "e/only.png", "", Verdict::Fail, "e/only.png: no actual image to compare it with", std::nullopt}, base, {}},
  };
  const fs::path folder = dir / "report";
  ReportFolder report(folder.string());
  std::vector<ReportCase> cases;
  for (std::size_t i = 0; i < compared.size(); ++i) cases.push_back(report.writeImages(static_cast<int>(i) + 1, compared[i], t));
  CHECK(cases[0].expected.path == "images/001-a_b_.expected.png");
  CHECK(cases[1].heatMap.path == "images/002-edge.diff.png");
  CHECK(cases[4].actual.path.empty());
  CHECK(cases[4].heatMap.path.empty());
  const std::string page = report.finish(cases, {"e", "a", t});
  CHECK(page == (folder / "index.html").string());
  for (const ReportCase& c : cases)
    for (const ReportImage* image : {&c.expected, &c.actual, &c.heatMap})
      if (!image->path.empty()) CHECK(readPng((folder / image->path).string()).width() == 10);

  std::ifstream in(page);
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Worst first: the file without a partner (100%), the edge (10%), the pixel (1%), the warning, the pass.
  CHECK(positionOf(html, "only.png") < positionOf(html, "edge.png"));
  CHECK(positionOf(html, "edge.png") < positionOf(html, "one_pixel.png"));
  CHECK(positionOf(html, "one_pixel.png") < positionOf(html, "off_by_one.png"));
  CHECK(positionOf(html, "off_by_one.png") < positionOf(html, "a&lt;b&gt;.png"));
  CHECK(html.find("a<b>") == std::string::npos);  // names are escaped
  CHECK(html.find("src=\"images/002-edge.diff.png\"") != std::string::npos);
  CHECK(html.find("e/only.png: no actual image to compare it with") != std::string::npos);
  // Self-contained: nothing fetched from anywhere, no script.
  CHECK(html.find("http") == std::string::npos);
  CHECK(html.find("<script") == std::string::npos);
  CHECK(html.find("<title>facet diff: FAILURE, 5 cases</title>") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("the summary line counts the verdicts and gives the exit code of the worst") {
  std::vector<DiffCase> cases(4);
  cases[0].verdict = Verdict::Pass;
  cases[1].verdict = Verdict::Fail;
  cases[2].verdict = Verdict::Fail;
  cases[3].verdict = Verdict::DifferentSize;
  CHECK(summaryLine(cases) == "4 cases: 1 pass, 2 failures, 1 size mismatch -> DIFFERENT SIZES (exit code 3)");
}
