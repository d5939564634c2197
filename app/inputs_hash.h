#pragma once
// What `facet batch --resume` compares to decide that an output is up to
// date: a hash of everything the image depends on that facet can see.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace facet {

// FNV-1a, 64 bits: not cryptographic, only a change detector, and small
// enough to need no library.
class Fnv1a64 {
 public:
  void add(std::string_view bytes);
  // A field with its length first, so that ("ab", "c") and ("a", "bc") differ.
  void addField(std::string_view bytes);
  std::uint64_t value() const { return state_; }
  std::string hex() const;  // 16 lower-case hex digits

 private:
  std::uint64_t state_ = 0xcbf29ce484222325ull;
};

// The bytes of `files` (each with its name; a file that cannot be read
// counts by its name alone, and its job fails when it is loaded), as 16 hex
// digits: what a scene was read from, or what its settings name.
std::string filesDigest(const std::vector<std::string>& files, std::uint64_t maxBytesEach);

// The inputs of one frame: the digest of the files it is drawn from (the
// glTF and the buffers and images it names, the maps the settings name; for
// builtin:NAME the name), the resolved settings as JSON text, the size, the
// backend and facet's version.
std::string inputsHash(std::string_view filesDigestOrName, std::string_view settingsJson, int width, int height,
                       std::string_view backend, std::string_view version);

}  // namespace facet
