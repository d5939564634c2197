#pragma once
#include <string>

#include "image/image.h"

namespace facet {

// Writes `image` as an 8-bit RGBA PNG, top row first, atomically (no partial
// file on failure). Throws facet::Error naming the path.
void writePng(const std::string& path, const Image& image);

// Reads a PNG (any bit depth and channel count stb_image accepts) into RGBA8.
// Throws facet::Error naming the path and the problem.
Image readPng(const std::string& path);

}  // namespace facet
