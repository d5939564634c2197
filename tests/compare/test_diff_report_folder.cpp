// A report folder is complete or absent: a write that fails part way (the
// disk is full after N files) leaves no new folder and the older report as it
// was; only a complete report replaces one, and never a folder of other work.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <unistd.h>

#include <doctest/doctest.h>

#include "common/error.h"
#include "compare/diff_report_folder.h"
#include "compare/image_diff.h"
#include "image/png.h"
#include "test_images.h"
#include "scratch_folder.h"

using namespace facet;
using namespace facet::test;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return scratchFolder("report", name); }

std::vector<std::string> namesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) names.push_back(fs::relative(entry.path(), dir).string());
  std::sort(names.begin(), names.end());
  return names;
}

// Writers that fail like a full disk once `allowed` files are written (the
// page counts as the last file).
ReportWriters failingAfter(int allowed, int& written) {
  const ReportWriters real = defaultReportWriters();
  const auto spend = [allowed, &written](const std::string& path) {
    if (written == allowed) throw Error(path + ": write failed (No space left on device)");
    ++written;
  };
  return {[=](const std::string& path, const Image& image) { spend(path), real.png(path, image); },
          [=](const std::string& path, std::string_view text) { spend(path), real.text(path, text); }};
}

// `count` cases of two images and a heat map each: 3 * count + 1 files with the page.
std::string writeReport(const fs::path& folder, int count, ReportWriters writers, const std::string& title) {
  const Image base(8, 8, kSlate);
  const DiffThresholds t;
  ReportFolder report(folder.string(), std::move(writers));
  std::vector<ReportCase> cases;
  for (int i = 0; i < count; ++i) {
    const Image actual = withPixel(base, i % 8, 0, {200, 20, 40, 255});
    const ComparedFiles compared{DiffCase{"case" + std::to_string(i) + ".png", "e", "a", Verdict::Fail, "", compareImages(base, actual, t)},
                                 base, actual};
    cases.push_back(report.writeImages(i + 1, compared, t));
  }
  return report.finish(cases, {title, "a", t});
}

}  // namespace

TEST_CASE("a report that fails after N files leaves no folder, and an older report stays as it was") {
  const fs::path dir = scratch("failing");
  const fs::path folder = dir / "report";
  for (const int allowed : {0, 1, 5, 12}) {  // 12: every image written, the page fails
    CAPTURE(allowed);
    int written = 0;
    const std::string message = [&] {
      try {
        writeReport(folder, 4, failingAfter(allowed, written), "first");
      } catch (const Error& e) {
        return std::string(e.what());
      }
      return std::string("(nothing thrown)");
    }();
    CHECK(written == allowed);
    CHECK(message.find(": write failed (No space left on device)") != std::string::npos);
    CHECK(message.rfind(folder.string() + "/", 0) == 0);  // named where the user looks, not by the temporary name
    CHECK(!fs::exists(folder));
    CHECK(fs::is_empty(dir));  // no temporary folder beside it either
  }

  writeReport(folder, 4, defaultReportWriters(), "first");
  const std::vector<std::string> before = namesIn(folder);
  const std::string page = readAll(folder / "index.html");
  REQUIRE(before.size() == 15);  // facet-report.txt, index.html, images/, 12 images
  for (const int allowed : {0, 3, 6}) {  // 6: a second report of two cases, its page fails
    CAPTURE(allowed);
    int written = 0;
    CHECK_THROWS_AS(writeReport(folder, 2, failingAfter(allowed, written), "second"), Error);
    CHECK(namesIn(folder) == before);
    CHECK(readAll(folder / "index.html") == page);
    CHECK(namesIn(dir).size() == before.size() + 1);  // the report and nothing beside it
  }
  fs::remove_all(dir);
}

TEST_CASE("a complete report replaces an older one entirely") {
  const fs::path dir = scratch("replace");
  const fs::path folder = dir / "report";
  writeReport(folder, 4, defaultReportWriters(), "first");
  const std::string page = writeReport(folder, 1, defaultReportWriters(), "second");
  CHECK(page == (folder / "index.html").string());
  CHECK(readAll(folder / "index.html").find("second") != std::string::npos);
  CHECK(namesIn(folder) == std::vector<std::string>{"facet-report.txt", "images", "images/001-case0.actual.png", "images/001-case0.diff.png",
                                                    "images/001-case0.expected.png", "index.html"});
  CHECK(readPng((folder / "images" / "001-case0.diff.png").string()).width() == 8);
  CHECK(namesIn(dir).size() == 7);
  fs::remove_all(dir);
}

TEST_CASE("a folder that is not a report is never replaced by one") {
  const fs::path dir = scratch("foreign");
  const fs::path folder = dir / "work";
  fs::create_directories(folder / "images");
  std::ofstream(folder / "index.html") << "my page";
  std::ofstream(folder / "images" / "photo.jpg") << "jpeg";
  CHECK_THROWS_WITH_AS(writeReport(folder, 1, defaultReportWriters(), "x"),
                       (folder.string() + ": is a folder that is not a facet report (it holds images/photo.jpg); give a new folder or remove this one").c_str(),
                       Error);
  fs::remove(folder / "images" / "photo.jpg");
  std::ofstream(folder / "notes.txt") << "notes";
  CHECK_THROWS_WITH_AS(checkReportFolder(folder.string(), {}),
                       (folder.string() + ": is a folder that is not a facet report (it holds notes.txt); give a new folder or remove this one").c_str(),
                       Error);
  CHECK(readAll(folder / "index.html") == "my page");
  CHECK(readAll(folder / "notes.txt") == "notes");
  CHECK(namesIn(dir).size() == 4);
  fs::remove(folder / "notes.txt");
  // index.html and images/*.png only, a report's shape (someone's web page), but no marker: kept.
  std::ofstream(folder / "images" / "photo.png") << "png";
  CHECK_THROWS_WITH_AS(writeReport(folder, 1, defaultReportWriters(), "x"),
                       (folder.string() + ": is a folder that is not a facet report (facet writes facet-report.txt in each of its reports); give a new folder or remove this one").c_str(),
                       Error);
  CHECK(readAll(folder / "index.html") == "my page");
  CHECK(readAll(folder / "images" / "photo.png") == "png");
  // An empty folder is taken.
  fs::remove_all(folder);
  fs::create_directories(folder);
  writeReport(folder, 1, defaultReportWriters(), "x");
  CHECK(fs::is_regular_file(folder / "facet-report.txt"));
  fs::remove_all(dir);
}
