#pragma once
// A report folder on disk: index.html (diff_report_html.h) and, under
// images/, each case's expected, actual and heat-map PNGs, so the folder can
// be moved or archived as a whole.
#include <string>
#include <vector>

#include "compare/compare_files.h"
#include "compare/diff_report_html.h"

namespace facet {

// Creates `folder` and folder/images if needed; throws facet::Error naming
// the folder when it cannot.
void createReportFolder(const std::string& folder);

// Writes the images of one case as images/NNN-NAME.{expected,actual,diff}.png
// (`index` gives NNN and keeps names unique; NAME is the case name with
// anything but letters, digits, '-', '_' and '.' replaced by '_'), and
// returns the case with the paths relative to the folder. Throws
// facet::Error naming a file that cannot be written.
ReportCase writeReportImages(const std::string& folder, int index, const ComparedFiles& compared, const DiffThresholds& thresholds);

// Writes folder/index.html atomically and returns its path.
std::string writeReportPage(const std::string& folder, std::vector<ReportCase> cases, const ReportContext& context);

}  // namespace facet
