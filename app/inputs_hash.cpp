#include "inputs_hash.h"

#include <cstdio>

#include "common/atomic_file.h"
#include "common/error.h"

namespace facet {

void Fnv1a64::add(std::string_view bytes) {
  for (const char c : bytes) {
    state_ ^= static_cast<std::uint8_t>(c);
    state_ *= 0x100000001b3ull;
  }
}

void Fnv1a64::addField(std::string_view bytes) {
  add(std::to_string(bytes.size()));
  add(":");
  add(bytes);
}

std::string Fnv1a64::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(state_));
  return text;
}

std::string filesDigest(const std::vector<std::string>& files, std::uint64_t maxBytesEach) {
  Fnv1a64 hash;
  for (const std::string& file : files) {
    hash.addField(file);
    try {
      hash.addField(readFile(file, maxBytesEach));
    } catch (const Error&) {
      hash.addField("");  // unreadable: loading it fails the job, which then writes nothing
    }
  }
  return hash.hex();
}

std::string inputsHash(std::string_view sceneBytesOrName, std::string_view settingsJson, int width, int height,
                       std::string_view backend, std::string_view version) {
  Fnv1a64 hash;
  hash.addField(sceneBytesOrName);
  hash.addField(settingsJson);
  hash.addField(std::to_string(width) + "x" + std::to_string(height));
  hash.addField(backend);
  hash.addField(version);
  return hash.hex();
}

}  // namespace facet
