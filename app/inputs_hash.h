#pragma once
// What `facet batch --resume` compares to decide that an output is up to
// date: a hash of everything the image depends on that facet can see.
#include <cstdint>
#include <string>
#include <string_view>

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

// The inputs of one frame: the scene file's bytes (or, for builtin:NAME and
// the default scene, the name), the resolved settings as JSON text, the size,
// the backend and facet's version. Files a glTF refers to (.bin, textures)
// are not read: change the .gltf or the settings to force a new render.
std::string inputsHash(std::string_view sceneBytesOrName, std::string_view settingsJson, int width, int height,
                       std::string_view backend, std::string_view version);

}  // namespace facet
