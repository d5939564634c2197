// The volume readers' shared file check.
#include "volume/volume_file.h"

#include <cerrno>
#include <filesystem>
#include <system_error>

#include "common/atomic_file.h"
#include "common/error.h"

namespace facet {

void requireRegularFile(const std::string& path, const std::string& shown) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec && ec.value() != ENOENT && ec.value() != ENOTDIR) throw Error(shown + ": " + describeErrno(ec.value()));
  if (ec || !fs::exists(status)) throw Error(shown + ": no such file");
  if (!fs::is_regular_file(status)) throw Error(shown + ": not a regular file");
}

}  // namespace facet
