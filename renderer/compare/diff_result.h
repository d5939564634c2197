#pragma once
// What compareImages finds. Differences are absolute, in 8-bit levels
// (0..255). Positions are Image coordinates: x to the right, y = 0 at the
// bottom row (as Image::at); text and HTML reports flip y to count from the
// top row, as image viewers do.
#include <array>
#include <cstdint>
#include <limits>
#include <string_view>

#include "image/image.h"
#include "image/stored_channels.h"

namespace facet {

enum class DiffStatus { Pass, Warn, Fail, Count };
inline constexpr std::array<std::string_view, 3> kDiffStatusNames = {"PASS", "WARNING", "FAILURE"};
static_assert(kDiffStatusNames.size() == static_cast<std::size_t>(DiffStatus::Count));

// An inclusive rectangle of pixels; empty until a pixel is added.
struct PixelBox {
  int minX = std::numeric_limits<int>::max(), minY = std::numeric_limits<int>::max();
  int maxX = -1, maxY = -1;

  bool empty() const { return maxX < 0; }
  void add(int x, int y);
};

struct ChannelDiff {
  int max = 0;        // 8-bit levels
  double mean = 0.0;  // 8-bit levels, over every pixel
};

// Where idiff puts its "Max error": the first channel that differs by the
// largest amount, in reading order (rows from the top, each left to right,
// then R, G, B, A).
struct WorstPixel {
  int x = -1, y = -1;  // Image coordinates; -1 when the images are equal
  int channel = -1;    // 0..3: R, G, B, A
  int difference = 0;  // that channel's difference, 8-bit levels
  Rgba8 expected, actual;
};

struct DiffResult {
  int width = 0, height = 0;
  std::array<ChannelDiff, 4> channels;  // R, G, B, A
  int maxDifference = 0;                // largest over the four channels, 8-bit levels
  // idiff's figures, averaged over the channels the files store
  // (storedChannels) of every pixel, here in 8-bit levels: idiff prints them
  // divided by 255.
  StoredChannels storedChannels;
  double meanError = 0.0;  // mean absolute difference
  double rmse = 0.0;       // root of the mean squared difference
  double psnr = std::numeric_limits<double>::infinity();  // dB, 20 log10(255 / rmse)

  std::int64_t differingPixels = 0;  // any channel differs at all
  std::int64_t failingPixels = 0;    // some channel over failThreshold
  std::int64_t warningPixels = 0;    // some channel over warnThreshold
  double failingPercent = 0.0;       // of all pixels, 0..100
  double warningPercent = 0.0;       // of all pixels, 0..100
  PixelBox differing;                // around every differing pixel
  PixelBox failing;                  // around every failing pixel
  WorstPixel worst;

  DiffStatus status = DiffStatus::Pass;

  std::int64_t pixelCount() const { return static_cast<std::int64_t>(width) * height; }
};

}  // namespace facet
