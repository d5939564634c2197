#include "compare/diff_report_folder.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "common/atomic_file.h"
#include "common/error.h"
#include "compare/heat_map.h"
#include "image/png.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

// Safe in a file name and in a URL without escaping.
std::string safeName(const std::string& name) {
  std::string out = name;
  for (char& c : out)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return out;
}

bool isPngName(const fs::path& name) {
  std::string ext = name.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png";
}

// The file facet writes in every report folder: a folder without it is not
// one of facet's, whatever it holds (someone's web page has index.html and
// images/*.png too).
constexpr const char* kReportMarker = "facet-report.txt";

// What a report folder holds: the marker, index.html, images/ and PNG files
// in it. A folder with anything else is someone's work, and never replaced.
std::string foreignEntry(const fs::path& folder) {
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if ((name == "index.html" || name == kReportMarker) && entry.is_regular_file(ec) && !entry.is_symlink(ec)) continue;
    if (name == "images" && entry.is_directory(ec) && !entry.is_symlink(ec)) {
      for (const fs::directory_entry& image : fs::directory_iterator(entry.path(), ec))
        if (!isPngName(image.path()) || !image.is_regular_file(ec) || image.is_symlink(ec)) return "images/" + image.path().filename().string();
      if (ec) return "images";
      continue;
    }
    return name;
  }
  return ec ? std::string(".") : std::string();
}

// Runs one write into the staged folder; an error names the file where the
// user will look for it (FOLDER/images/...), not under the temporary name.
template <typename Write>
void writeStaged(const std::string& staged, const std::string& folder, Write&& write) {
  try {
    write();
  } catch (const Error& e) {
    std::string message = e.what();
    std::string name = folder;
    while (name.size() > 1 && name.back() == '/') name.pop_back();
    if (const auto at = message.find(staged); at != std::string::npos) message.replace(at, staged.size(), name);
    throw Error(message);
  }
}

}  // namespace

ReportWriters defaultReportWriters() {
  return {[](const std::string& path, const Image& image) { writePng(path, image); },
          [](const std::string& path, std::string_view text) { writeFileAtomically(path, text); }};
}

void checkReportFolder(const std::string& folder, const std::vector<std::string>& inputs) {
  checkOutputFolder(folder, inputs);
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return;
  if (const std::string entry = foreignEntry(folder); !entry.empty())
    throw Error(shownPath(folder) + ": is a folder that is not a facet report (it holds " + shownPath(entry) +
                "); give a new folder or remove this one");
  if (!fs::is_empty(folder, ec) && !fs::is_regular_file(fs::path(folder) / kReportMarker, ec))
    throw Error(shownPath(folder) + ": is a folder that is not a facet report (facet writes " + kReportMarker +
                " in each of its reports); give a new folder or remove this one");
}

ReportFolder::ReportFolder(const std::string& folder, ReportWriters writers)
    : folder_((checkReportFolder(folder, {}), folder)), writers_(std::move(writers)), staged_(folder) {
  std::error_code ec;
  fs::create_directory(fs::path(staged_.path()) / "images", ec);
  if (ec) throw Error(shownPath(folder) + ": cannot create the report folder (" + ec.message() + ")");
}

ReportCase ReportFolder::writeImages(int index, const ComparedFiles& compared, const DiffThresholds& thresholds) {
  char prefix[16];
  std::snprintf(prefix, sizeof prefix, "images/%03d-", index);
  const std::string stem = prefix + safeName(fs::path(compared.diffCase.name).stem().string());
  const auto write = [&](const std::string& relative, const Image& image) -> ReportImage {
    if (image.empty()) return {};
    writeStaged(staged_.path(), folder_, [&] { writers_.png((fs::path(staged_.path()) / relative).string(), image); });
    return {relative, image.width(), image.height()};
  };
  ReportCase out;
  out.diffCase = compared.diffCase;
  out.expected = write(stem + ".expected.png", compared.expected);
  out.actual = write(stem + ".actual.png", compared.actual);
  if (compared.diffCase.result) out.heatMap = write(stem + ".diff.png", heatMap(compared.expected, compared.actual, thresholds));
  return out;
}

std::string ReportFolder::finish(std::vector<ReportCase> cases, const ReportContext& context) {
  const std::string html = reportHtml(std::move(cases), context);
  writeStaged(staged_.path(), folder_, [&] { writers_.text((fs::path(staged_.path()) / "index.html").string(), html); });
  writeStaged(staged_.path(), folder_, [&] {
    writers_.text((fs::path(staged_.path()) / kReportMarker).string(), "a report of facet diff: facet diff -o may replace this folder\n");
  });
  staged_.commit();
  return (fs::path(folder_) / "index.html").string();
}

}  // namespace facet
