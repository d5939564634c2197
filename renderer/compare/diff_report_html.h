#pragma once
// The HTML page of a folder comparison: one self-contained file (inline
// style, no script, nothing from the network) that shows, per case and
// worst case first, the expected image, the actual image and the heat map
// side by side with the case's figures.
#include <string>
#include <vector>

#include "compare/diff_case.h"
#include "compare/diff_thresholds.h"

namespace facet {

struct ReportImage {
  std::string path;  // relative to the page, URL-safe; empty: no such image
  int width = 0, height = 0;
};

struct ReportCase {
  DiffCase diffCase;
  ReportImage expected, actual, heatMap;
};

struct ReportContext {
  std::string expectedSource;  // the EXPECTED argument, as given
  std::string actualSource;    // the ACTUAL argument, as given
  DiffThresholds thresholds;
};

// The whole page; cases may come in any order, the page sorts them worst
// first (worseThan).
std::string reportHtml(std::vector<ReportCase> cases, const ReportContext& context);

}  // namespace facet
