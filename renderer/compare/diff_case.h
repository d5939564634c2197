#pragma once
// One comparison case: a pair of files (or a file without its partner) and
// what became of it. A Verdict's value is the exit code idiff gives it.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compare/diff_result.h"

namespace facet {

// Ordered by severity; the worst over all cases is the exit code of
// `facet diff`, as in OpenImageIO's idiff.
enum class Verdict : int {
  Pass = 0,           // within the warn thresholds
  Warn = 1,           // over the warn thresholds, within the fail thresholds
  Fail = 2,           // over the fail thresholds, or a file with no partner
  DifferentSize = 3,  // the images cannot be compared pixel by pixel
  FileError = 4,      // a file is missing, unreadable or not a PNG
  Count
};
inline constexpr std::array<std::string_view, 5> kVerdictNames = {"PASS", "WARNING", "FAILURE", "DIFFERENT SIZES", "FILE ERROR"};
static_assert(kVerdictNames.size() == static_cast<std::size_t>(Verdict::Count));

std::string_view verdictName(Verdict verdict);
Verdict verdictOf(DiffStatus status);

struct DiffCase {
  std::string name;          // the file name the two sides share
  std::string expectedPath;  // empty: the expected side has no such file
  std::string actualPath;    // empty: the actual side has no such file
  Verdict verdict = Verdict::Pass;
  std::string problem;              // one line, when the pixels were not compared
  std::optional<DiffResult> result; // the figures, when they were
};

Verdict worstVerdict(const std::vector<DiffCase>& cases);  // Pass when there are none

// The report's order, worst first: by verdict, then (a file without partner
// counting as 100%) by the percentage of failing pixels, then the largest
// difference, the RMSE, and last the name.
bool worseThan(const DiffCase& a, const DiffCase& b);

}  // namespace facet
