#include "image/png_text.h"

#include <zlib.h>

#include "common/error.h"

namespace facet {
namespace {

constexpr std::size_t kSignatureBytes = 8;
constexpr std::size_t kIendBytes = 12;  // length 0, "IEND", CRC

std::uint32_t bigEndian32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<std::uint8_t>(bytes[at + i]);
  return v;
}

}  // namespace

std::vector<std::uint8_t> withTextChunk(std::vector<std::uint8_t> png, std::string_view keyword, std::string_view text) {
  if (keyword.empty() || keyword.size() > 79) throw Error("PNG text keyword must be 1 to 79 characters");
  for (const char c : keyword)
    if (static_cast<unsigned char>(c) < 32 || c == 127) throw Error("PNG text keyword must be printable");
  const std::string_view all(reinterpret_cast<const char*>(png.data()), png.size());
  if (png.size() < kSignatureBytes + kIendBytes || all.substr(png.size() - 8, 4) != "IEND")
    throw Error("PNG text: the image does not end with IEND");
  std::string chunk = "tEXt";
  chunk.append(keyword).push_back('\0');
  chunk.append(text);
  const std::uint32_t length = static_cast<std::uint32_t>(chunk.size() - 4);
  const std::uint32_t crc = static_cast<std::uint32_t>(crc32(0L, reinterpret_cast<const Bytef*>(chunk.data()), static_cast<uInt>(chunk.size())));
  std::vector<std::uint8_t> bytes;
  for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(static_cast<std::uint8_t>(length >> shift));
  bytes.insert(bytes.end(), chunk.begin(), chunk.end());
  for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(static_cast<std::uint8_t>(crc >> shift));
  png.insert(png.end() - static_cast<std::ptrdiff_t>(kIendBytes), bytes.begin(), bytes.end());
  return png;
}

std::optional<std::string> textChunk(std::string_view png, std::string_view keyword) {
  for (std::size_t at = kSignatureBytes; at + 12 <= png.size();) {
    const std::uint64_t length = bigEndian32(png, at);
    if (at + 12 + length > png.size()) return std::nullopt;
    const std::string_view type = png.substr(at + 4, 4);
    const std::string_view data = png.substr(at + 8, length);
    if (type == "IEND") return std::nullopt;
    if (type == "tEXt") {
      const std::size_t nul = data.find('\0');
      if (nul != std::string_view::npos && data.substr(0, nul) == keyword) return std::string(data.substr(nul + 1));
    }
    at += 12 + length;
  }
  return std::nullopt;
}

}  // namespace facet
