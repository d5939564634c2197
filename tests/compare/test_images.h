#pragma once
// Small images for the comparison tests, built in code so no binary file is
// committed. Coordinates are Image coordinates (y = 0 at the bottom row).
#include "image/image.h"

namespace facet::test {

inline constexpr Rgba8 kSlate = {10, 20, 40, 255};
inline constexpr Rgba8 kWhite = {255, 255, 255, 255};
inline constexpr Rgba8 kBlack = {0, 0, 0, 255};

// `image` with one pixel replaced.
Image withPixel(Image image, int x, int y, Rgba8 color);

// `image` with `levels` added to R, G and B of every pixel (clamped).
Image shifted(Image image, int levels);

// A black image with a white object over the columns [fromX, toX): moving
// toX by one moves the object's right edge by one pixel.
Image objectImage(int width, int height, int fromX, int toX);

}  // namespace facet::test
