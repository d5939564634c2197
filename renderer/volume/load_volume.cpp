// loadVolume: the built-in test signal or a volume file, chosen by name.
#include "volume/load_volume.h"

#include <string_view>

#include "common/atomic_file.h"
#include "common/error.h"

namespace facet {

Volume loadVolume(const std::string& path, int resolution) {
  switch (volumeFormatOf(path)) {
    case VolumeFormat::MarschnerLobb: return makeMarschnerLobb(resolution);
    case VolumeFormat::Nrrd: return readNrrd(path);
    case VolumeFormat::Nifti: return readNifti(path);
    case VolumeFormat::None: break;
  }
  if (path.rfind("builtin:", 0) == 0) throw Error(shownPath(path) + ": no such built-in volume (there is builtin:marschner-lobb)");
  throw Error(shownPath(path) + ": unknown volume format (supported: .nrrd, .nhdr, .nii, .nii.gz, builtin:marschner-lobb)");
}

}  // namespace facet
