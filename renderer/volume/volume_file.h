#pragma once
// What the volume readers share: the check that a path is a file before a
// library opens it, how messages show numbers and axes, and the one table of
// sample types, which NRRD and NIfTI-1 name alike.
#include <cstddef>
#include <string>
#include <vector>

#include "scene/volume.h"

namespace facet {

// Throws facet::Error "<shown>: no such file" or "not a regular file" (or
// the system's reason), before a reader hands `path` to its library.
void requireRegularFile(const std::string& path, const std::string& shown);

// Throws facet::Error "<shown>: ..." when the volume's box along an axis,
// (samples - 1)·spacing, is past kMaxVolumeExtent, or its largest spacing
// is more than kMaxVolumeSpacingRatio times its smallest. Both readers call
// it once the sizes and spacings are known, before reading samples.
void requireBoundedBox(const Volume& volume, const std::string& shown);

// A number as a message shows it: "-2", "0.5", "inf".
std::string shownNumber(double value);
inline constexpr const char* kAxisNames[3] = {"x", "y", "z"};

// NIfTI-1's scl_slope and scl_inter: a sample v stands for slope·v +
// intercept (in double) when slope ≠ 0, for v itself otherwise. NRRD has none.
struct SampleScale {
  double slope = 0.0, intercept = 0.0;
};

// The samples at `bytes`, each in the file's byte order (reversed when
// `swap`), as floats: values.size() of them, scaled by `scale`.
using SampleConversion = void (*)(const unsigned char* bytes, bool swap, SampleScale scale, std::vector<float>& values);

// A file's sample type: how messages name it, its bytes and signedness, and
// how a sample becomes a float (none: facet does not read the type).
struct SampleType {
  const char* name = "";  // as messages say it: "int16", "float64"
  std::size_t bytes = 0;
  bool isSigned = false;
  SampleConversion toFloat = nullptr;
};

// The numeric sample types of both formats (teem's nrrdType*, NIfTI-1's
// DT_*); facet reads the first five. Each reader maps its format's codes here.
enum class SampleKind { Int8, UInt8, Int16, UInt16, Float32, Int32, UInt32, Int64, UInt64, Float64, Count };
const SampleType& sampleType(SampleKind kind);

// The types facet reads, as a refusal lists them: "int8, uint8, int16, uint16 and float32".
std::string readSampleTypeNames();

}  // namespace facet
