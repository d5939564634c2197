#pragma once
// Reading two PNG files and comparing them, with every way that can go
// wrong turned into the case's verdict rather than an exception.
#include <string>

#include "compare/diff_case.h"
#include "compare/diff_thresholds.h"
#include "image/image.h"

namespace facet {

struct ComparedFiles {
  DiffCase diffCase;
  Image expected;  // empty when absent or unreadable
  Image actual;    // empty when absent or unreadable
};

// Either path may be empty (that side has no such file: Verdict::Fail, as
// for a file present in only one folder). Unreadable or non-PNG files give
// Verdict::FileError, sizes that differ Verdict::DifferentSize; `problem`
// then says which file and why. Thresholds must pass checkThresholds.
// The mean error, RMSE and PSNR average over the channels the two files
// store (unionOf), as idiff's do. A file without alpha reads as opaque, so
// an RGB file equals an RGBA file of the same opaque pixels, where idiff
// takes the missing alpha for 0.
ComparedFiles compareFiles(const std::string& name, const std::string& expectedPath, const std::string& actualPath,
                           const DiffThresholds& thresholds);

}  // namespace facet
