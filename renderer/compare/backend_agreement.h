#pragma once
// How far the OpenGL backend and the CPU backend may differ on one frame:
// not at all. Both follow renderer/PIPELINE.md to the float operation
// (llvmpipe's coverage and plane equations, shading arithmetic made of exact
// operations in one order, the same sRGB tables), so each pixel is the same
// byte on both sides; any difference fails. The one place this is said: the
// agreement suite, the viewer's reference view and `facet diff --agreement`
// (which the viewer's window tests call) all read it here. A case of the
// agreement suite may allow a measured difference only with a reason
// written in its JSON (tests/agreement/cases).
#include <array>
#include <string_view>

#include "compare/diff_result.h"
#include "compare/diff_thresholds.h"

namespace facet {

inline DiffThresholds backendAgreement() {
  DiffThresholds t;
  t.failThreshold = 0.0;  // a pixel fails when any channel differs at all
  t.failPercent = 0.0;
  t.warnThreshold = 0.0;
  t.warnPercent = 0.0;
  return t;
}

// The verdict on two backends' images as the agreement suite gives it:
// identical (every byte equal), within tolerance (pixels differ, none beyond
// the thresholds compared with: a case's measured allowance), or different.
enum class Agreement { Identical, WithinTolerance, Different, Count };
inline constexpr std::array<std::string_view, static_cast<std::size_t>(Agreement::Count)> kAgreementNames = {"identical", "within tolerance",
                                                                                                           "different"};
inline Agreement agreementOf(const DiffResult& d) {
  if (d.differingPixels == 0) return Agreement::Identical;
  return d.status == DiffStatus::Fail ? Agreement::Different : Agreement::WithinTolerance;
}

}  // namespace facet
