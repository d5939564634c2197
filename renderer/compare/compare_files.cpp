#include "compare/compare_files.h"

#include <utility>

#include "common/error.h"
#include "compare/image_diff.h"
#include "image/png.h"

namespace facet {
namespace {

std::string sizeText(const Image& image) { return std::to_string(image.width()) + "x" + std::to_string(image.height()); }

// Reads one side; a failure becomes the case's problem (the first one found).
PngImage readSide(const std::string& path, DiffCase& diffCase) {
  if (path.empty()) return {};
  try {
    return readPngImage(path);
  } catch (const Error& e) {
    if (diffCase.problem.empty()) {
      diffCase.verdict = Verdict::FileError;
      diffCase.problem = e.what();
    }
    return {};
  }
}

}  // namespace

ComparedFiles compareFiles(const std::string& name, const std::string& expectedPath, const std::string& actualPath,
                           const DiffThresholds& thresholds) {
  ComparedFiles out;
  DiffCase& c = out.diffCase;
  c.name = name;
  c.expectedPath = expectedPath;
  c.actualPath = actualPath;
  PngImage expected = readSide(expectedPath, c);
  PngImage actual = readSide(actualPath, c);
  out.expected = std::move(expected.image);
  out.actual = std::move(actual.image);
  if (!c.problem.empty()) return out;

  if (expectedPath.empty() || actualPath.empty()) {
    c.verdict = Verdict::Fail;
    c.problem = expectedPath.empty() ? actualPath + ": no expected image to compare it with"
                                     : expectedPath + ": no actual image to compare it with";
    return out;
  }
  if (out.expected.width() != out.actual.width() || out.expected.height() != out.actual.height()) {
    c.verdict = Verdict::DifferentSize;
    c.problem = "images of different sizes: " + expectedPath + " is " + sizeText(out.expected) + ", " + actualPath + " is " +
                sizeText(out.actual);
    return out;
  }
  c.result = compareImages(out.expected, out.actual, thresholds, unionOf(expected.channels, actual.channels));
  c.verdict = verdictOf(c.result->status);
  return out;
}

}  // namespace facet
