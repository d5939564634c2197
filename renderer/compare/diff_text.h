#pragma once
// The terminal report of `facet diff`: a block of figures per case and one
// summary line.
#include <string>
#include <vector>

#include "compare/diff_case.h"
#include "compare/diff_thresholds.h"

namespace facet {

// "NAME: VERDICT" and the figures, or the problem, indented below it; ends
// with a newline. Positions and boxes count y from the top row.
std::string caseText(const DiffCase& diffCase, const DiffThresholds& thresholds);

// "5 cases: 1 pass, 1 warning, 3 failures -> FAILURE (exit code 2)", no newline.
std::string summaryLine(const std::vector<DiffCase>& cases);

}  // namespace facet
