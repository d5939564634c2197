#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "image/image.h"
#include "image/stored_channels.h"
#include "settings/render_settings.h"

namespace facet {

// The largest PNG facet reads, checked from the header before anything is
// decoded: the largest image facet renders. Each side at most kMaxImageSide,
// and at most kMaxPngDecodedBytes for the RGBA samples at the file's bit
// depth (4 bytes a pixel, 8 for 16-bit files), the largest buffer the
// decoder builds: a 16384x16384 8-bit PNG fits, a 16-bit one up to 2^27 pixels.
inline constexpr std::uint64_t kMaxPngDecodedBytes = 4ull * kMaxImageSide * kMaxImageSide;  // 1 GiB
inline constexpr std::uint64_t kMaxPngFileBytes = 512ull << 20;

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
