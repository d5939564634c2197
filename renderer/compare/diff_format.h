#pragma once
// How the figures of a comparison are written, the same in the terminal
// and in the HTML report.
#include <cstdint>
#include <string>

#include "compare/diff_result.h"

namespace facet {

// Four significant digits; "inf" for infinity.
std::string formatNumber(double value);

// A figure as idiff prints it: six significant digits ("%g"), "inf" for
// infinity.
std::string formatIdiffNumber(double value);

// The channels a figure averages over, as idiff names them: "R, G, B, A",
// "R, G, B", "Y, A" or "Y".
std::string formatChannels(StoredChannels channels);

// One channel (0..3: R, G, B, A) by its idiff name; a grey file's is Y.
std::string formatChannel(int channel, StoredChannels channels);

// A threshold as a fraction of full scale with its 8-bit equivalent:
// "0.003922 (1/255)", "0.004 (1.02/255)", "off" for kNoLimit.
std::string formatThreshold(double fraction);

// The pixels allowed over a threshold: "0.5%", or with allowFailures set
// (above 0) "0.5% or up to 3 pixels".
std::string formatAllowed(double percent, std::int64_t allowFailures = 0);

// "1 pixel", "12 pixels".
std::string formatPixels(std::int64_t count);

// "#rrggbbaa".
std::string formatColor(Rgba8 color);

// A box counted from the top-left, as image viewers show pixels:
// "x 3..7, y 0..2"; "none" when empty. `imageHeight` flips y.
std::string formatBox(const PixelBox& box, int imageHeight);

// A pixel position counted from the top-left: "(3, 5)".
std::string formatPosition(int x, int y, int imageHeight);

}  // namespace facet
