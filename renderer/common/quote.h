#pragma once
// How an error line shows a value taken from the input: quoted, at most a
// short prefix, control and non-UTF-8 bytes escaped, so that one line stays
// one short line whatever the input holds (a 15 MB value, a NUL, raw bytes).
#include <cstddef>
#include <string>
#include <string_view>

namespace facet {

// The longest prefix of a value an error line quotes, in bytes of input.
inline constexpr std::size_t kMaxQuotedBytes = 48;

// (Not "quoted": std::quoted would win by argument-dependent lookup.)
// "'text'", or "'prefix…' (N bytes)" when longer than kMaxQuotedBytes;
// bytes below 0x20, 0x7f and bytes that are not UTF-8 appear as \xNN.
std::string quoteInput(std::string_view text);

// A count for a message, the noun in the singular when one: "1 sampler",
// "3 samplers". Nouns with other plurals pass both forms.
std::string countOf(std::size_t n, std::string_view noun);
std::string countOf(std::size_t n, std::string_view one, std::string_view many);

}  // namespace facet
