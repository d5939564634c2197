#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "image/image.h"
#include "image/stored_channels.h"

#include "vocabulary/limits.h"

namespace facet {

// An 8-bit RGBA PNG of `image`, top row first. Throws facet::OutOfMemory.
std::vector<std::uint8_t> encodePng(const Image& image, const std::string& name);

// Writes encodePng(image) to `path` atomically (no partial file on failure).
// Throws facet::Error naming the path, facet::OutOfMemory.
void writePng(const std::string& path, const Image& image);

// A decoded PNG and the channels its file stores, counted as libpng
// expands them (a palette to RGB, a tRNS chunk to alpha), which is how
// OpenImageIO, and so idiff, reads the file.
struct PngImage {
  Image image;
  StoredChannels channels;
};

// Decodes a PNG (any bit depth and colour type of the PNG standard) into
// RGBA8; 16-bit samples keep their high byte. Strict: every chunk's CRC
// must match, the file must end with IEND, nothing may follow it, and an
// unknown critical chunk is refused. Throws facet::Error naming `name` and
// the problem, facet::OutOfMemory.
PngImage decodePngImage(std::string_view bytes, const std::string& name);
Image decodePng(std::string_view bytes, const std::string& name);  // decodePngImage's image

// readFile (at most kMaxPngFileBytes) and decodePngImage.
PngImage readPngImage(const std::string& path);
Image readPng(const std::string& path);  // readPngImage's image

}  // namespace facet
