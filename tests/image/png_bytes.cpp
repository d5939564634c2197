#include "png_bytes.h"

#include <vector>

namespace facet::test {
namespace {

std::string bigEndian32(std::uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8), static_cast<char>(v)};
}

// Deflate's bit order: values least significant bit first, Huffman codes
// most significant bit first.
struct BitWriter {
  std::string bytes;
  std::uint32_t pending = 0;
  int count = 0;
  void bit(std::uint32_t b) {
    pending |= (b & 1u) << count;
    if (++count == 8) {
      bytes += static_cast<char>(pending);
      pending = 0;
      count = 0;
    }
  }
  void value(std::uint32_t v, int bits) {
    for (int i = 0; i < bits; ++i) bit(v >> i);
  }
  void code(std::uint32_t c, int bits) {
    for (int i = bits - 1; i >= 0; --i) bit(c >> i);
  }
  void flush() {
    while (count != 0) bit(0);
  }
};

int samples(int colorType) { return colorType == 2 ? 3 : colorType == 4 ? 2 : colorType == 6 ? 4 : 1; }

std::uint32_t adler32(std::string_view raw) {
  std::uint32_t a = 1, b = 0;
  for (const char c : raw) {
    a = (a + static_cast<std::uint8_t>(c)) % 65521u;
    b = (b + a) % 65521u;
  }
  return (b << 16) | a;
}

}  // namespace

std::uint32_t crc32Bitwise(std::string_view bytes) {
  std::uint32_t c = 0xffffffffu;
  for (const char byte : bytes) {
    c ^= static_cast<std::uint8_t>(byte);
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ ((c & 1u) ? 0xedb88320u : 0u);
  }
  return ~c;
}

std::string pngChunk(std::string_view type, std::string_view data) {
  const std::string body = std::string(type) + std::string(data);
  return bigEndian32(static_cast<std::uint32_t>(data.size())) + body + bigEndian32(crc32Bitwise(body));
}

std::string ihdrChunk(std::uint32_t width, std::uint32_t height, int bitDepth, int colorType, int interlace) {
  return pngChunk("IHDR", bigEndian32(width) + bigEndian32(height) +
                              std::string{static_cast<char>(bitDepth), static_cast<char>(colorType), 0, 0, static_cast<char>(interlace)});
}

std::string pngFile(std::string_view chunks) { return "\x89PNG\r\n\x1a\n" + std::string(chunks) + pngChunk("IEND", ""); }

std::string zlibStored(std::string_view raw) {
  std::string out = "\x78\x01";
  std::size_t at = 0;
  do {
    const std::size_t n = std::min<std::size_t>(raw.size() - at, 65535);
    const bool last = at + n == raw.size();
    out += static_cast<char>(last ? 1 : 0);
    out += {static_cast<char>(n), static_cast<char>(n >> 8), static_cast<char>(~n), static_cast<char>(~n >> 8)};
    out.append(raw.substr(at, n));
    at += n;
  } while (at < raw.size());
  return out + bigEndian32(adler32(raw));
}

std::string zlibZeros(std::uint64_t count) {
  BitWriter w;
  w.bytes = "\x78\x01";
  w.value(1, 1);  // BFINAL
  w.value(1, 2);  // BTYPE 01: fixed Huffman codes
  std::uint64_t left = count;
  if (left > 0) {
    w.code(0x30, 8);  // literal 0
    --left;
  }
  for (; left >= 258; left -= 258) {
    w.code(0xc5, 8);  // length 258 (symbol 285)
    w.code(0, 5);     // distance 1 (code 0)
  }
  for (; left > 0; --left) w.code(0x30, 8);
  w.code(0, 7);  // end of block (symbol 256)
  w.flush();
  const auto b = static_cast<std::uint32_t>(count % 65521u);  // every byte is 0: a stays 1
  return w.bytes + bigEndian32((b << 16) | 1u);
}

std::uint64_t filteredSize(std::uint32_t width, std::uint32_t height, int bitDepth, int colorType, int interlace) {
  const std::uint64_t bits = static_cast<std::uint64_t>(samples(colorType)) * static_cast<std::uint64_t>(bitDepth);
  const auto rows = [&](std::uint64_t w, std::uint64_t h) { return w == 0 || h == 0 ? 0 : h * (1 + (w * bits + 7) / 8); };
  if (!interlace) return rows(width, height);
  std::uint64_t total = 0;
  // Adam7 pass p starts at (x0, y0) and steps by (dx, dy).
  const int x0[7] = {0, 4, 0, 2, 0, 1, 0}, y0[7] = {0, 0, 4, 0, 2, 0, 1}, dx[7] = {8, 8, 4, 4, 2, 2, 1}, dy[7] = {8, 8, 8, 4, 4, 2, 2};
  for (int p = 0; p < 7; ++p) {
    std::uint64_t w = 0, h = 0;
    for (std::uint64_t x = static_cast<std::uint64_t>(x0[p]); x < width; x += static_cast<std::uint64_t>(dx[p])) ++w;
    for (std::uint64_t y = static_cast<std::uint64_t>(y0[p]); y < height; y += static_cast<std::uint64_t>(dy[p])) ++h;
    total += rows(w, h);
  }
  return total;
}

std::string zeroPng(std::uint32_t width, std::uint32_t height, int bitDepth, int colorType, int interlace, bool compressed) {
  const std::uint64_t size = filteredSize(width, height, bitDepth, colorType, interlace);
  std::string chunks = ihdrChunk(width, height, bitDepth, colorType, interlace);
  if (colorType == 3) chunks += pngChunk("PLTE", std::string(3, '\0'));
  chunks += pngChunk("IDAT", compressed ? zlibZeros(size) : zlibStored(std::string(size, '\0')));
  return pngFile(chunks);
}

}  // namespace facet::test
