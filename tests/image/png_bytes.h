#pragma once
// PNG files built byte by byte, for the tests of the reader: chunks with
// their CRCs (computed here bit by bit, apart from the reader's table), and
// image data as stored (uncompressed) deflate blocks or as a run of zero
// bytes in fixed-Huffman matches.
#include <cstdint>
#include <string>
#include <string_view>

namespace facet::test {

// CRC-32 of ISO 3309, one bit at a time.
std::uint32_t crc32Bitwise(std::string_view bytes);

// Length, type, data and CRC.
std::string pngChunk(std::string_view type, std::string_view data);

// The IHDR chunk.
std::string ihdrChunk(std::uint32_t width, std::uint32_t height, int bitDepth = 8, int colorType = 6, int interlace = 0);

// The signature, `chunks`, and an IEND chunk.
std::string pngFile(std::string_view chunks);

// A zlib stream holding `raw` in stored blocks.
std::string zlibStored(std::string_view raw);

// A zlib stream of `count` zero bytes: one literal, then matches of 258
// (13 bits each in the fixed code), about 160 bytes out for one in.
std::string zlibZeros(std::uint64_t count);

// The bytes an image's data inflates to: each row of each pass (seven for
// Adam7) one filter byte and its packed samples.
std::uint64_t filteredSize(std::uint32_t width, std::uint32_t height, int bitDepth, int colorType, int interlace);

// A whole PNG whose samples are all zero (a PLTE of one black entry for colour
// type 3), its data in stored blocks or, with `compressed`, zlibZeros.
std::string zeroPng(std::uint32_t width, std::uint32_t height, int bitDepth = 8, int colorType = 6, int interlace = 0,
                    bool compressed = false);

}  // namespace facet::test
