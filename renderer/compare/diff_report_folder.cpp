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

ReportImage writeImage(const std::string& folder, const std::string& relative, const Image& image) {
  if (image.empty()) return {};
  writePng((fs::path(folder) / relative).string(), image);
  return {relative, image.width(), image.height()};
}

}  // namespace

void createReportFolder(const std::string& folder) {
  std::error_code ec;
  fs::create_directories(fs::path(folder) / "images", ec);
  if (ec) throw Error(folder + ": cannot create the report folder (" + ec.message() + ")");
}

ReportCase writeReportImages(const std::string& folder, int index, const ComparedFiles& compared, const DiffThresholds& thresholds) {
  char prefix[16];
  std::snprintf(prefix, sizeof prefix, "images/%03d-", index);
  const std::string stem = prefix + safeName(fs::path(compared.diffCase.name).stem().string());
  ReportCase out;
  out.diffCase = compared.diffCase;
  out.expected = writeImage(folder, stem + ".expected.png", compared.expected);
  out.actual = writeImage(folder, stem + ".actual.png", compared.actual);
  if (compared.diffCase.result) out.heatMap = writeImage(folder, stem + ".diff.png", heatMap(compared.expected, compared.actual, thresholds));
  return out;
}

std::string writeReportPage(const std::string& folder, std::vector<ReportCase> cases, const ReportContext& context) {
  const std::string html = reportHtml(std::move(cases), context);
  const std::string path = (fs::path(folder) / "index.html").string();
  writeFileAtomically(path, {reinterpret_cast<const std::uint8_t*>(html.data()), html.size()});
  return path;
}

}  // namespace facet
