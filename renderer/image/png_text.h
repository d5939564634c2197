#pragma once
// PNG tEXt chunks (PNG 1.2, section 4.2.3.1): a keyword and a Latin-1 text
// that travel inside the file, e.g. the inputs a frame was rendered from.
// Readers ignore chunks they do not know, so the image reads as before.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facet {

// `png` (a whole PNG, as encodePng makes) with a tEXt chunk keyword=text
// inserted before IEND. The keyword is 1-79 printable Latin-1 characters;
// throws facet::Error when it is not, or when `png` does not end with IEND.
std::vector<std::uint8_t> withTextChunk(std::vector<std::uint8_t> png, std::string_view keyword, std::string_view text);

// The text of the first tEXt chunk named `keyword` in `png`, or nothing
// (also when the bytes are not a well-formed chunk list: the caller then
// treats the file as having no text).
std::optional<std::string> textChunk(std::string_view png, std::string_view keyword);

}  // namespace facet
