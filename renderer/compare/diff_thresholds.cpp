#include "compare/diff_thresholds.h"

#include <cmath>
#include <string>

#include "common/error.h"

namespace facet {
namespace {

void checkValue(const char* name, double value, double upper) {
  if (std::isnan(value) || value < 0.0 || value > upper)
    throw Error(std::string("diff threshold ") + name + ": " + std::to_string(value) + " is outside [0, " +
                (std::isinf(upper) ? std::string("inf") : std::to_string(upper)) + "]");
}

}  // namespace

void checkThresholds(const DiffThresholds& t) {
  checkValue("fail", t.failThreshold, kNoLimit);
  checkValue("failpercent", t.failPercent, 100.0);
  checkValue("hardfail", t.hardFail, kNoLimit);
  if (t.allowFailures < 0) throw Error("diff threshold allowfailures: " + std::to_string(t.allowFailures) + " is below 0");
  checkValue("warn", t.warnThreshold, kNoLimit);
  checkValue("warnpercent", t.warnPercent, 100.0);
  checkValue("hardwarn", t.hardWarn, kNoLimit);
}

int toleratedLevels(double fraction) {
  // The slack absorbs the rounding in 1.0 / 255 * 255, so that exactly one
  // step, written as a fraction, tolerates one step.
  constexpr double kSlack = 1e-6;  // 8-bit levels
  const double levels = fraction * 255.0 + kSlack;
  if (!(levels < 255.0)) return 255;
  return levels < 0.0 ? 0 : static_cast<int>(std::floor(levels));
}

}  // namespace facet
