// What the volume readers share: the file check, numbers in messages, the sample types.
#include "volume/volume_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <system_error>
#include <type_traits>

#include "common/atomic_file.h"
#include "common/error.h"
#include "vocabulary/limits.h"

namespace facet {
namespace {

template <typename T>
void convert(const unsigned char* bytes, bool swap, SampleScale scale, std::vector<float>& values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, bytes + i * sizeof(T), sizeof(T));
    if (swap) std::reverse(b, b + sizeof(T));
    T v;
    std::memcpy(&v, b, sizeof(T));
    values[i] = scale.slope != 0.0 ? static_cast<float>(scale.slope * static_cast<double>(v) + scale.intercept) : static_cast<float>(v);
  }
}

// A type facet reads: its bytes and signedness are the C++ type's it converts from.
template <typename T>
constexpr SampleType readType(const char* name) {
  return {name, sizeof(T), std::is_signed_v<T>, convert<T>};
}

// Indexed by SampleKind.
constexpr SampleType kSampleTypes[] = {
    readType<std::int8_t>("int8"),
    readType<std::uint8_t>("uint8"),
    readType<std::int16_t>("int16"),
    readType<std::uint16_t>("uint16"),
    readType<float>("float32"),
    {"int32", 4, true},
    {"uint32", 4, false},
    {"int64", 8, true},
    {"uint64", 8, false},
    {"float64", 8, true},
};
static_assert(std::size(kSampleTypes) == static_cast<std::size_t>(SampleKind::Count));

}  // namespace

void requireRegularFile(const std::string& path, const std::string& shown) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec && ec.value() != ENOENT && ec.value() != ENOTDIR) throw Error(shown + ": " + describeErrno(ec.value()));
  if (ec || !fs::exists(status)) throw Error(shown + ": no such file");
  if (!fs::is_regular_file(status)) throw Error(shown + ": not a regular file");
}

void requireBoundedBox(const Volume& volume, const std::string& shown) {
  for (int a = 0; a < 3; ++a) {
    const double extent = static_cast<double>(volume.size[a] - 1) * static_cast<double>(volume.spacing[a]);
    if (!(extent <= kMaxVolumeExtent))
      throw Error(shown + ": " + std::to_string(volume.size[a]) + " samples " + shownNumber(volume.spacing[a]) + " apart along " + kAxisNames[a] +
                  " span " + shownNumber(extent) + ", more than facet's limit of " + shownNumber(kMaxVolumeExtent));
  }
  const double smallest = std::min({volume.spacing.x, volume.spacing.y, volume.spacing.z});
  const double largest = std::max({volume.spacing.x, volume.spacing.y, volume.spacing.z});
  if (!(largest <= smallest * kMaxVolumeSpacingRatio))
    throw Error(shown + ": spacings " + shownNumber(volume.spacing.x) + ", " + shownNumber(volume.spacing.y) + " and " + shownNumber(volume.spacing.z) +
                ": the largest is more than " + shownNumber(kMaxVolumeSpacingRatio) + " times the smallest, facet's limit");
}

std::string shownNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

const SampleType& sampleType(SampleKind kind) { return kSampleTypes[static_cast<std::size_t>(kind)]; }

std::string readSampleTypeNames() {
  std::vector<std::string> names;
  for (const SampleType& type : kSampleTypes)
    if (type.toFloat) names.push_back(type.name);
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return text;
}

}  // namespace facet
