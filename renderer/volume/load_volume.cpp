// loadVolume: the built-in test signal or a volume file, chosen by name.
#include "volume/load_volume.h"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "common/atomic_file.h"
#include "common/error.h"

namespace facet {
namespace {

constexpr std::string_view kBuiltin = "builtin:";

// File name extensions compare without case: HEAD.NII is as much NIfTI as head.nii.
bool endsWith(std::string_view path, std::string_view suffix) {
  if (path.size() < suffix.size()) return false;
  return std::equal(suffix.begin(), suffix.end(), path.end() - static_cast<std::ptrdiff_t>(suffix.size()), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
  });
}

}  // namespace

bool isVolumeName(const std::string& path) {
  return path == "builtin:marschner-lobb" || endsWith(path, ".nrrd") || endsWith(path, ".nhdr") || endsWith(path, ".nii") || endsWith(path, ".nii.gz");
}

Volume loadVolume(const std::string& path, int resolution) {
  if (path == "builtin:marschner-lobb") return makeMarschnerLobb(resolution);
  if (path.rfind(kBuiltin, 0) == 0) throw Error(shownPath(path) + ": no such built-in volume (there is builtin:marschner-lobb)");
  if (endsWith(path, ".nrrd") || endsWith(path, ".nhdr")) return readNrrd(path);
  if (endsWith(path, ".nii") || endsWith(path, ".nii.gz")) return readNifti(path);
  throw Error(shownPath(path) + ": unknown volume format (supported: .nrrd, .nhdr, .nii, .nii.gz, builtin:marschner-lobb)");
}

}  // namespace facet
