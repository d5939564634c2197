// libFuzzer target: the PNG reader on arbitrary bytes, as `facet diff` reads
// a file (readPng is readFile and decodePng). Every input must end in an
// image or a facet::Error: never a crash, an out-of-bounds access,
// undefined behaviour, or an allocation the size limit should have stopped.
// An image it decodes must come back the same through the writer.
//
// The CRC of every complete chunk is recomputed first: a mutated chunk would
// otherwise almost never get past the CRC check into the decoder. (The check
// itself is tested in tests/image; a finding saved from here has right CRCs,
// so `facet diff` on the file replays it too.)
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "common/error.h"
#include "image/png.h"

namespace {

std::uint32_t crc32(std::string_view bytes) {
  std::uint32_t c = 0xffffffffu;
  for (const char byte : bytes) {
    c ^= static_cast<std::uint8_t>(byte);
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ ((c & 1u) ? 0xedb88320u : 0u);
  }
  return ~c;
}

void repairCrcs(std::string& png) {
  std::size_t at = 8;  // after the signature
  while (at <= png.size() && png.size() - at >= 12) {
    std::uint32_t length = 0;
    for (std::size_t i = 0; i < 4; ++i) length = (length << 8) | static_cast<std::uint8_t>(png[at + i]);
    if (length > png.size() - at - 12) return;
    const std::uint32_t crc = crc32(std::string_view(png).substr(at + 4, 4 + std::size_t{length}));
    for (std::size_t i = 0; i < 4; ++i) png[at + 8 + length + i] = static_cast<char>(crc >> (24 - 8 * i));
    at += 12 + std::size_t{length};
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string png(reinterpret_cast<const char*>(data), size);
  if (png.size() >= 8) repairCrcs(png);
  facet::Image image;
  try {
    image = facet::decodePng(png, "fuzz.png");
  } catch (const facet::Error&) {
    return 0;
  }
  const std::vector<std::uint8_t> encoded = facet::encodePng(image, "fuzz.png");
  if (facet::decodePng(std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()), "fuzz.png") != image) std::abort();
  return 0;
}
