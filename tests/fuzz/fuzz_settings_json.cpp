// libFuzzer target: a settings file, as `--settings FILE` reads it
// (loadSettingsFile: the bytes go through a file, so the reading is the
// same). Every input must end in RenderSettings or a facet::Error. Settings
// that load must write out as JSON that loads back to the same JSON.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "settings/settings_json.h"

namespace {

// One file per process, rewritten for every input (in memory where /dev/shm is).
const std::string& inputPath() {
  static const std::string path = [] {
    std::string pattern = std::string(access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp") + "/fuzz_settings_XXXXXX";
    const int fd = mkstemp(pattern.data());
    if (fd < 0) std::abort();
    close(fd);
    std::atexit([] { std::remove(inputPath().c_str()); });
    return pattern;
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = inputPath();
  const int fd = open(path.c_str(), O_WRONLY | O_TRUNC);
  if (fd < 0 || write(fd, data, size) != static_cast<ssize_t>(size) || close(fd) != 0) std::abort();
  facet::RenderSettings settings;
  try {
    settings = facet::loadSettingsFile(path);
  } catch (const facet::Error&) {
    return 0;
  }
  const nlohmann::json written = facet::settingsToJson(settings);
  if (facet::settingsToJson(facet::settingsFromJson(written)) != written) std::abort();
  return 0;
}
