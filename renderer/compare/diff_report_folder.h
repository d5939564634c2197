#pragma once
// A report folder on disk: index.html (diff_report_html.h) and, under
// images/, each case's expected, actual and heat-map PNGs, so the folder can
// be moved or archived as a whole. It is complete or absent: written under a
// temporary name beside its place (common/output_folder.h) and put there only
// once index.html is written, replacing an older report in the same step.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "common/output_folder.h"
#include "compare/compare_files.h"
#include "compare/diff_report_html.h"
#include "image/image.h"

namespace facet {

// How the report's files reach the disk: writePng and writeFileAtomically
// unless the caller passes others (a test: one that fails after N files).
struct ReportWriters {
  std::function<void(const std::string& path, const Image& image)> png;
  std::function<void(const std::string& path, std::string_view text)> text;
};
ReportWriters defaultReportWriters();

// Checks, before any work, that `folder` can take a report: checkOutputFolder
// (common/output_folder.h), and an existing folder is replaced only when it
// is empty or holds nothing but a report's index.html and images/*.png.
// Throws facet::Error naming the folder.
void checkReportFolder(const std::string& folder, const std::vector<std::string>& inputs);

class ReportFolder {
 public:
  // checkReportFolder(folder, {}), then the temporary folder with images/.
  explicit ReportFolder(const std::string& folder, ReportWriters writers = defaultReportWriters());

  // Writes the images of one case as images/NNN-NAME.{expected,actual,diff}.png
  // (`index` gives NNN and keeps names unique; NAME is the case name with
  // anything but letters, digits, '-', '_' and '.' replaced by '_'), and
  // returns the case with the paths relative to the folder. Throws
  // facet::Error naming a file that cannot be written; the report is then
  // never put in place.
  ReportCase writeImages(int index, const ComparedFiles& compared, const DiffThresholds& thresholds);

  // Writes index.html, puts the folder in its place and returns the page's
  // path there (folder/index.html).
  std::string finish(std::vector<ReportCase> cases, const ReportContext& context);

 private:
  std::string folder_;
  ReportWriters writers_;
  StagedFolder staged_;
};

}  // namespace facet
