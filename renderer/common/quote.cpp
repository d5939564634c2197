#include "common/quote.h"

#include <cstdint>
#include <cstdio>

namespace facet {
namespace {

// Length of the well-formed UTF-8 sequence starting at text[i], or 0.
std::size_t utf8Length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
  const std::uint8_t b = byte(i);
  std::size_t n = 0;
  std::uint32_t code = 0;
  if (b < 0x80) return 1;
  if ((b & 0xe0) == 0xc0) n = 2, code = b & 0x1f;
  else if ((b & 0xf0) == 0xe0) n = 3, code = b & 0x0f;
  else if ((b & 0xf8) == 0xf0) n = 4, code = b & 0x07;
  else return 0;
  if (i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3f);
  }
  // Overlong forms, surrogates and values past U+10FFFF are not UTF-8.
  static constexpr std::uint32_t kMinimum[5] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < kMinimum[n] || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return 0;
  return n;
}

}  // namespace

std::string quoteInput(std::string_view text) {
  std::string out = "'";
  std::size_t i = 0;
  while (i < text.size() && i < kMaxQuotedBytes) {
    const std::size_t n = utf8Length(text, i);
    const auto b = static_cast<unsigned char>(text[i]);
    if (n == 0 || b < 0x20 || b == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", b);
      out += escaped;
      i += 1;
    } else {
      out.append(text.substr(i, n));
      i += n;
    }
  }
  if (i < text.size()) return out + "...' (" + std::to_string(text.size()) + " bytes)";
  return out + "'";
}

std::string countOf(std::size_t n, std::string_view one, std::string_view many) {
  return std::to_string(n) + " " + std::string(n == 1 ? one : many);
}

std::string countOf(std::size_t n, std::string_view noun) { return countOf(n, noun, std::string(noun) + "s"); }

}  // namespace facet
