#include "compare/diff_case.h"

#include <algorithm>
#include <tuple>

namespace facet {
namespace {

// A case that never reached the pixels (no partner, unreadable) ranks as if
// every pixel failed.
double failingPercentOf(const DiffCase& c) { return c.result ? c.result->failingPercent : 100.0; }
int maxDifferenceOf(const DiffCase& c) { return c.result ? c.result->maxDifference : 255; }
double rmseOf(const DiffCase& c) { return c.result ? c.result->rmse : 255.0; }

}  // namespace

std::string_view verdictName(Verdict verdict) { return kVerdictNames[static_cast<std::size_t>(verdict)]; }

Verdict verdictOf(DiffStatus status) {
  switch (status) {
    case DiffStatus::Pass: return Verdict::Pass;
    case DiffStatus::Warn: return Verdict::Warn;
    case DiffStatus::Fail:
    case DiffStatus::Count: break;
  }
  return Verdict::Fail;
}

Verdict worstVerdict(const std::vector<DiffCase>& cases) {
  Verdict worst = Verdict::Pass;
  for (const DiffCase& c : cases) worst = std::max(worst, c.verdict);
  return worst;
}

bool worseThan(const DiffCase& a, const DiffCase& b) {
  const auto key = [](const DiffCase& c) { return std::tuple(c.verdict, failingPercentOf(c), maxDifferenceOf(c), rmseOf(c)); };
  if (key(a) != key(b)) return key(a) > key(b);
  return a.name < b.name;
}

}  // namespace facet
