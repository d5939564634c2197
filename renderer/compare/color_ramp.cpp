#include "compare/color_ramp.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace facet {
namespace {

struct Knot {
  int index;  // into the original 256-entry table; t = index / 255
  double r, g, b;  // 8-bit
};

// Every 16th entry of the 256-entry table, and the last, rounded to 8 bits;
// linear between them stays within 2 levels of the full table.
constexpr std::array<Knot, 17> kInferno = {{
    {0, 0, 0, 4},        {16, 11, 7, 36},     {32, 33, 12, 74},    {48, 61, 9, 101},
    {64, 87, 16, 110},   {80, 113, 25, 110},  {96, 138, 34, 106},  {112, 163, 44, 97},
    {128, 188, 55, 84},  {144, 210, 70, 68},  {160, 228, 90, 49},  {176, 241, 115, 29},
    {192, 249, 142, 9},  {208, 252, 172, 17}, {224, 249, 203, 53}, {240, 242, 234, 105},
    {255, 252, 255, 164},
}};

std::uint8_t level(double v) { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }

}  // namespace

Rgba8 inferno(double t) {
  const double position = std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0) * 255.0;  // in table entries
  std::size_t i = 0;
  while (i + 2 < kInferno.size() && position > kInferno[i + 1].index) ++i;
  const Knot& lo = kInferno[i];
  const Knot& hi = kInferno[i + 1];
  const double s = (position - lo.index) / (hi.index - lo.index);
  return {level(lo.r + s * (hi.r - lo.r)), level(lo.g + s * (hi.g - lo.g)), level(lo.b + s * (hi.b - lo.b)), 255};
}

}  // namespace facet
