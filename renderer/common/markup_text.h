#pragma once
// Text inside the markup facet writes (the diff report's HTML, the JUnit XML
// of batch, the SVG plots), as character data or an attribute value.
#include <string>
#include <string_view>

namespace facet {

// & < > " ' as entities; the control characters XML 1.0 forbids (all below
// 0x20 but tab and newline) as spaces, so the file stays well-formed.
std::string markupEscaped(std::string_view text);

}  // namespace facet
