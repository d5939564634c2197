#include "compare/diff_format.h"

#include <cmath>
#include <cstdio>

#include "compare/diff_thresholds.h"

namespace facet {

std::string formatNumber(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::string formatIdiffNumber(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string formatChannels(StoredChannels channels) {
  return std::string(channels.colour ? "R, G, B" : "Y") + (channels.alpha ? ", A" : "");
}

std::string formatChannel(int channel, StoredChannels channels) {
  constexpr const char* kNames[4] = {"R", "G", "B", "A"};
  if (channel == 0 && !channels.colour) return "Y";
  return channel >= 0 && channel < 4 ? kNames[channel] : "?";
}

std::string formatThreshold(double fraction) {
  if (fraction == kNoLimit) return "off";
  char text[64];
  std::snprintf(text, sizeof text, "%.4g (%s/255)", fraction, formatNumber(fraction * 255.0).c_str());
  return text;
}

std::string formatAllowed(double percent, std::int64_t allowFailures) {
  return formatNumber(percent) + "%" + (allowFailures > 0 ? " or up to " + formatPixels(allowFailures) : "");
}

std::string formatPixels(std::int64_t count) { return std::to_string(count) + (count == 1 ? " pixel" : " pixels"); }

std::string formatColor(Rgba8 c) {
  char text[16];
  std::snprintf(text, sizeof text, "#%02x%02x%02x%02x", c.r, c.g, c.b, c.a);
  return text;
}

std::string formatBox(const PixelBox& box, int imageHeight) {
  if (box.empty()) return "none";
  char text[80];
  std::snprintf(text, sizeof text, "x %d..%d, y %d..%d", box.minX, box.maxX, imageHeight - 1 - box.maxY, imageHeight - 1 - box.minY);
  return text;
}

std::string formatPosition(int x, int y, int imageHeight) {
  char text[40];
  std::snprintf(text, sizeof text, "(%d, %d)", x, imageHeight - 1 - y);
  return text;
}

}  // namespace facet
