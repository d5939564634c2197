#include "image/png.h"

#include <cstdint>
#include <cstring>
#include <vector>

#include <stb_image.h>
#include <stb_image_write.h>

#include "common/atomic_file.h"
#include "common/error.h"

namespace facet {
namespace {

constexpr std::uint64_t kMaxPngBytes = 512ull << 20;
constexpr int kMaxPngSide = 32768;

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

void writePng(const std::string& path, const Image& image) {
  if (image.empty()) throw Error(path + ": refusing to write an empty image");
  const int w = image.width(), h = image.height();
  const int stride = w * 4;
  // Top row first in the file: start at the last stored row and step backwards.
  const auto* lastRow = reinterpret_cast<const std::uint8_t*>(image.data()) + static_cast<std::size_t>(h - 1) * static_cast<std::size_t>(stride);
  std::vector<std::uint8_t> encoded;
  if (!stbi_write_png_to_func(appendBytes, &encoded, w, h, 4, lastRow, -stride) || encoded.empty())
    throw Error(path + ": PNG encoding failed");
  writeFileAtomically(path, encoded);
}

Image readPng(const std::string& path) {
  const std::string bytes = readFile(path, kMaxPngBytes);
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = static_cast<int>(bytes.size());
  static constexpr unsigned char kMagic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kMagic, 8) != 0) throw Error(path + ": not a PNG file");
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(data, length, &w, &h, &channels)) throw Error(path + ": unreadable PNG header");
  if (w <= 0 || h <= 0 || w > kMaxPngSide || h > kMaxPngSide)
    throw Error(path + ": PNG size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range");
  stbi_uc* pixels = stbi_load_from_memory(data, length, &w, &h, &channels, 4);
  if (!pixels) throw Error(path + ": cannot decode PNG (" + stbi_failure_reason() + ")");
  Image image(w, h);
  const std::size_t stride = static_cast<std::size_t>(w) * 4;
  for (int y = 0; y < h; ++y)  // file row 0 is the top: it becomes stored row h-1
    std::memcpy(&image.at(0, h - 1 - y), pixels + static_cast<std::size_t>(y) * stride, stride);
  stbi_image_free(pixels);
  return image;
}

}  // namespace facet
