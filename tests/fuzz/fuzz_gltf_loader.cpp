// libFuzzer target: the glTF loader on arbitrary bytes, as a .gltf's JSON or
// a .glb (chosen by the bytes themselves, as the loader does). Every input
// must end in a Scene or a facet::Error; anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "scene/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    const facet::Scene scene = facet::loadGltfFromMemory(bytes, "fuzz.gltf", "");
    (void)scene.triangleCount();
    (void)scene.worldBounds();
  } catch (const facet::Error&) {
  }
  return 0;
}
