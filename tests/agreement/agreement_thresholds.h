#pragma once
// Every tolerance of the agreement suite, in one place. Units: per-channel
// differences in 8-bit levels, as fractions of full scale for DiffThresholds.
#include "compare/diff_thresholds.h"

namespace facet::agreement {

// OpenGL on llvmpipe against the CPU reference, same scene and settings.
//
// Coverage is held exactly (kMaxCoverageMismatches below): both backends
// snap the same clip coordinates to the same grid with the same tie rule.
// Colours are not bit-exact, for reasons of arithmetic, not of rules:
// - llvmpipe evaluates pow, exp2, log2 and 1/sqrt with its own polynomial
//   and Newton-step approximations, so a specular term or an sRGB encode can
//   land one 8-bit step away from glibc's result;
// - it interpolates attributes from plane equations set up at the first
//   vertex, the CPU from barycentric weights, so world positions differ in
//   the last bits of a float. Where a shadow-map compare or a spot cut-off
//   sits exactly on that edge, a pixel flips between lit and unlit.
// Hence: a pixel fails above 1 level (one rounding step); up to
// kFailPercent of pixels may fail (shadow and cut-off edges); none may
// differ by more than kHardFail.
inline DiffThresholds glVersusCpu() {
  DiffThresholds t;
  t.failThreshold = 1.0 / 255.0;
  t.failPercent = 0.5;
  t.hardFail = kNoLimit;
  t.warnThreshold = 0.0;
  t.warnPercent = 0.0;
  return t;
}

// The tight target the suite reports against (not a failure): every pixel
// within one level.
inline DiffThresholds tight() {
  DiffThresholds t;
  t.failThreshold = 1.0 / 255.0;
  t.failPercent = 0.0;
  return t;
}

// Pixels that one backend draws and the other leaves as background.
inline constexpr long kMaxCoverageMismatches = 0;

// A fresh CPU render against its committed golden: the CPU backend is
// deterministic (no fused multiply-add, no fast-math, one writer per
// pixel), so on the same libm it reproduces its goldens bit for bit; one
// level is allowed for a libm whose pow rounds differently.
inline DiffThresholds cpuVersusGolden() {
  DiffThresholds t;
  t.failThreshold = 1.0 / 255.0;
  t.failPercent = 0.0;
  return t;
}

}  // namespace facet::agreement
