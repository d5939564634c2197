// PNG read/write: rows flip once, round trips are exact, failures leave no
// file, and every kind of broken file is refused with its own message.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <doctest/doctest.h>
#include <stb_image.h>

#include "common/error.h"
#include "image/png.h"
#include "png_bytes.h"

using namespace facet;
namespace fs = std::filesystem;

TEST_CASE("a PNG round trip is exact, and the file starts with the top row") {
  Image image(3, 2, {10, 20, 30, 255});
  image.at(0, 1) = {255, 0, 0, 255};  // top-left (row 1 is the top of a 2-row image)
  image.at(2, 0) = {0, 0, 255, 128};  // bottom-right
  const fs::path path = fs::temp_directory_path() / "facet_test_roundtrip.png";
  writePng(path.string(), image);
  CHECK(readPng(path.string()) == image);

  int w = 0, h = 0, n = 0;
  unsigned char* raw = stbi_load(path.c_str(), &w, &h, &n, 4);
  REQUIRE(raw);
  CHECK(raw[0] == 255);                 // first pixel in the file: top-left, red
  CHECK(raw[(1 * 3 + 2) * 4 + 2] == 255);  // last row, last pixel: bottom-right, blue
  stbi_image_free(raw);
  fs::remove(path);
}

TEST_CASE("a failed write leaves no file, and bad PNGs are named errors") {
  const std::string missingDir = "/nonexistent-dir/out.png";
  CHECK_THROWS_WITH_AS(writePng(missingDir, Image(2, 2)), doctest::Contains(missingDir.c_str()), Error);
  CHECK_FALSE(fs::exists(missingDir));
  const fs::path notPng = fs::temp_directory_path() / "facet_test_not_a.png";
  {
    FILE* f = std::fopen(notPng.c_str(), "wb");
    std::fputs("hello", f);
    std::fclose(f);
  }
  CHECK_THROWS_WITH_AS(readPng(notPng.string()), doctest::Contains("not a PNG file"), Error);
  fs::remove(notPng);
  CHECK_THROWS_WITH_AS(writePng("/tmp/empty.png", Image()), doctest::Contains("empty image"), Error);
}

// The reader's refusals, on files built byte by byte (tests/image/png_bytes.h).
namespace {

using facet::test::ihdrChunk;
using facet::test::pngChunk;
using facet::test::pngFile;
using facet::test::zeroPng;
using facet::test::zlibStored;

// The message decodePng refuses `bytes` with; "" when it decodes them.
std::string refusal(const std::string& bytes) {
  try {
    (void)decodePng(bytes, "t.png");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// A valid 3x2 RGBA file from the writer (its own CRCs), with a tEXt chunk.
std::string validPng() {
  const std::vector<std::uint8_t> written = encodePng(Image(3, 2, {10, 20, 30, 255}), "t.png");
  std::string bytes(written.begin(), written.end());
  bytes.insert(33, pngChunk("tEXt", std::string("Comment\0hello", 13)));  // after the signature and IHDR
  return bytes;
}

std::size_t chunkAt(const std::string& bytes, const char* type) { return bytes.find(type) - 4; }

}  // namespace

TEST_CASE("PNG: a chunk whose CRC does not match is refused, naming the chunk") {
  const std::string good = validPng();
  REQUIRE(refusal(good).empty());
  for (const char* type : {"IHDR", "tEXt", "IDAT", "IEND"}) {
    CAPTURE(type);
    const std::size_t at = chunkAt(good, type);
    const std::size_t length = (static_cast<std::uint8_t>(good[at + 2]) << 8) | static_cast<std::uint8_t>(good[at + 3]);
    const std::string expected = "t.png: CRC error in chunk " + std::string(type) + " at byte " + std::to_string(at) + " (the file is damaged)";
    std::string bad = good;
    bad[at + 8 + length] = static_cast<char>(bad[at + 8 + length] ^ 0x80);  // the stored CRC
    CHECK(refusal(bad) == expected);
    if (length > 0) {
      bad = good;
      bad[at + 8 + length - 1] = static_cast<char>(bad[at + 8 + length - 1] ^ 0x01);  // the last data byte
      CHECK(refusal(bad) == expected);
    }
  }
}

TEST_CASE("PNG: every cut of a valid file is refused as empty, not a PNG, or truncated") {
  const std::string good = validPng();
  for (std::size_t n = 0; n < good.size(); ++n) {
    CAPTURE(n);
    const std::string message = refusal(good.substr(0, n));
    if (n == 0) CHECK(message == "t.png: empty file, not a PNG");
    else if (n < 8) CHECK(message == "t.png: not a PNG file");
    else CHECK(message.rfind("t.png: truncated PNG: ", 0) == 0);
  }
  CHECK(refusal(good.substr(0, good.size() - 12)) == "t.png: truncated PNG: no IEND chunk (the file ends at byte " +
                                                          std::to_string(good.size() - 12) + ")");
}

TEST_CASE("PNG: bytes after the IEND chunk are refused") {
  const std::string good = validPng();
  CHECK(refusal(good + "x") == "t.png: trailing data: 1 bytes after the IEND chunk at byte " + std::to_string(good.size() - 12));
  CHECK(refusal(good + good).find("trailing data: " + std::to_string(good.size()) + " bytes") != std::string::npos);
}

TEST_CASE("PNG: a size past the limit is refused from the header, before decoding") {
  // 20000x20000 claimed by 48 KB of data: refused by the side limit.
  const std::string data(48 * 1024, 'x');
  const std::string huge = pngFile(ihdrChunk(20000, 20000) + pngChunk("IDAT", data));
  CHECK(refusal(huge) == "t.png: PNG is 20000x20000 pixels, more than facet reads (at most 16384x16384, the largest image it renders)");
  CHECK(refusal(pngFile(ihdrChunk(16385, 1) + pngChunk("IDAT", data))).find("PNG is 16385x1 pixels, more than") != std::string::npos);
  CHECK(refusal(pngFile(ihdrChunk(1, 16385) + pngChunk("IDAT", data))).find("PNG is 1x16385 pixels, more than") != std::string::npos);
  // 16-bit samples: 8 bytes a pixel, so the decoded-bytes limit bites first.
  CHECK(refusal(pngFile(ihdrChunk(16384, 16384, 16, 2) + pngChunk("IDAT", data))) ==
        "t.png: PNG is 16384x16384 at 16 bits a channel, 2048 MiB decoded, more than facet reads (at most 1024 MiB, the largest image it renders)");
  CHECK(kMaxPngDecodedBytes == 4ull * kMaxImageSide * kMaxImageSide);
  // Within the limit, but far too little data for its size: deflate cannot
  // inflate 48 KB to 256 MB, so it is refused before the decoder allocates.
  CHECK(refusal(pngFile(ihdrChunk(16384, 16384, 8, 0) + pngChunk("IDAT", data))) ==
        "t.png: truncated or corrupt PNG: 49152 bytes of compressed image data cannot hold 16384x16384 pixels");
  // At the limit, a side is read.
  CHECK(decodePng(zeroPng(16384, 1, 8, 0), "t.png").width() == 16384);
  CHECK(decodePng(zeroPng(1, 16384, 1, 0), "t.png").height() == 16384);
}

TEST_CASE("PNG: every colour type and bit depth decodes, interlaced or not, and highly compressed data is accepted") {
  const struct {
    int colorType, bitDepth;
    Rgba8 pixel{};  // of all-zero samples
  } kinds[] = {{0, 1, {0, 0, 0, 255}}, {0, 2, {0, 0, 0, 255}}, {0, 4, {0, 0, 0, 255}}, {0, 8, {0, 0, 0, 255}}, {0, 16, {0, 0, 0, 255}},
               {2, 8, {0, 0, 0, 255}}, {2, 16, {0, 0, 0, 255}}, {3, 1, {0, 0, 0, 255}}, {3, 8, {0, 0, 0, 255}}, {4, 8, {0, 0, 0, 0}},
               {4, 16, {0, 0, 0, 0}},  {6, 8, {0, 0, 0, 0}},   {6, 16, {0, 0, 0, 0}}};
  for (const auto& kind : kinds)
    for (const int interlace : {0, 1})
      for (const auto& size : {std::pair{1u, 1u}, std::pair{13u, 7u}, std::pair{3u, 17u}}) {
        const unsigned w = size.first, h = size.second;  // named, not bound: CAPTURE's lambda takes them
        CAPTURE(kind.colorType);
        CAPTURE(kind.bitDepth);
        CAPTURE(interlace);
        CAPTURE(w);
        const Image image = decodePng(zeroPng(w, h, kind.bitDepth, kind.colorType, interlace), "t.png");
        CHECK(image == Image(static_cast<int>(w), static_cast<int>(h), kind.pixel));
      }
  // 4 MiB of samples in 26 KB: about 160 to 1, within deflate's 1032.
  const std::string dense = zeroPng(1024, 1024, 8, 6, 0, true);
  CHECK(dense.size() < 30000);
  CHECK(decodePng(dense, "t.png") == Image(1024, 1024, {0, 0, 0, 0}));
}

TEST_CASE("PNG: the channels a file stores are counted as libpng expands them, a palette to RGB and tRNS to alpha") {
  using namespace facet::test;
  const auto channelsOf = [](int colorType, bool transparency) {
    std::string chunks = ihdrChunk(2, 2, 8, colorType);
    if (colorType == 3) chunks += pngChunk("PLTE", std::string(3, '\0'));
    if (transparency) chunks += pngChunk("tRNS", colorType == 3 ? std::string(1, '\xff') : std::string(colorType == 2 ? 6 : 2, '\x01'));
    chunks += pngChunk("IDAT", zlibStored(std::string(filteredSize(2, 2, 8, colorType, 0), '\0')));
    return decodePngImage(pngFile(chunks), "t.png").channels;
  };
  CHECK(channelsOf(0, false) == StoredChannels{false, false});  // Y
  CHECK(channelsOf(0, true) == StoredChannels{false, true});    // Y, A
  CHECK(channelsOf(4, false) == StoredChannels{false, true});
  CHECK(channelsOf(2, false) == StoredChannels{true, false});   // R, G, B
  CHECK(channelsOf(2, true) == StoredChannels{true, true});
  CHECK(channelsOf(3, false) == StoredChannels{true, false});
  CHECK(channelsOf(3, true) == StoredChannels{true, true});
  CHECK(channelsOf(6, false) == StoredChannels{true, true});
  CHECK(StoredChannels{false, true}.count() == 2);
  CHECK(unionOf({false, true}, {true, false}) == StoredChannels{true, true});
}

TEST_CASE("PNG: broken image data is named, with a reason only when the decoder gives one") {
  const std::string header = ihdrChunk(4, 4, 8, 6);
  // A zlib stream whose first block is of type 3, which does not exist: stb_image sets no reason.
  const std::string noReason = pngFile(header + pngChunk("IDAT", std::string("\x78\x01\x07\0\0\0\0\0", 8)));
  // Stored data one row short: stb_image says "not enough pixels".
  const std::string short1 = pngFile(header + pngChunk("IDAT", zlibStored(std::string(4 * 17 - 17, '\0'))));
  CHECK(refusal(short1) == "t.png: corrupt PNG image data (not enough pixels)");
  CHECK(refusal(noReason) == "t.png: corrupt PNG image data");  // not the reason of the file before
}

TEST_CASE("PNG: a broken structure is named, an unknown ancillary chunk skipped") {
  const std::string header = ihdrChunk(2, 2, 8, 6);
  const std::string data = pngChunk("IDAT", zlibStored(std::string(2 * 9, '\0')));
  REQUIRE(refusal(pngFile(header + data)).empty());
  CHECK(refusal(pngFile(header + pngChunk("zzZz", "whatever") + data)).empty());
  // Empty IDAT chunks are valid, first, among or after the others (under
  // UBSan, the first one once made stb_image call memcpy with NULL).
  const std::string empty = pngChunk("IDAT", "");
  CHECK(decodePng(pngFile(header + empty + data + empty), "t.png") == Image(2, 2));
  CHECK(decodePng(pngFile(header + empty + empty + data), "t.png") == Image(2, 2));
  CHECK(refusal(pngFile(data + header)) == "t.png: corrupt PNG: the first chunk is IDAT, not IHDR");
  CHECK(refusal(pngFile(header + pngChunk("ABCD", "x") + data)) == "t.png: unsupported PNG: unknown critical chunk ABCD at byte 33");
  CHECK(refusal(pngFile(header + pngChunk(std::string("ID\0T", 4), "") + data)) ==
        "t.png: corrupt PNG: the chunk at byte 33 has type 'ID\\x00T', not four letters");
  CHECK(refusal(pngFile(header + header + data)) == "t.png: corrupt PNG: a second IHDR chunk at byte 33");
  CHECK(refusal(pngFile(header)) == "t.png: corrupt PNG: no image data (IDAT chunk)");
  CHECK(refusal(pngFile(header + data + pngChunk("tEXt", "a") + data)).find("after other chunks") != std::string::npos);
  CHECK(refusal(pngFile(ihdrChunk(2, 2, 3, 2) + data)) == "t.png: corrupt PNG: bit depth 3 is not allowed with colour type 2");
  CHECK(refusal(pngFile(ihdrChunk(2, 2, 8, 5) + data)) == "t.png: corrupt PNG: colour type 5 does not exist");
  CHECK(refusal(pngFile(ihdrChunk(0, 2) + data)) == "t.png: corrupt PNG: image size 0x2");
  CHECK(refusal(pngFile(ihdrChunk(2, 2, 8, 6, 2) + data)) == "t.png: corrupt PNG: unknown compression, filter or interlace method (0, 0, 2)");
  CHECK(refusal(pngFile(ihdrChunk(2, 2, 8, 3) + data)) == "t.png: corrupt PNG: a palette image with no PLTE chunk before its image data");
  CHECK(refusal(pngFile(pngChunk("IHDR", "short") + data)) == "t.png: corrupt PNG: IHDR holds 5 bytes, not 13");
  std::string endWithData = pngFile(header + data);
  endWithData.resize(endWithData.size() - 12);
  CHECK(refusal(endWithData + pngChunk("IEND", "x")) == "t.png: corrupt PNG: IEND holds 1 bytes, not 0");
}

TEST_CASE("PNG: the image data must be enough for the size, at deflate's ratio, every Adam7 pass counted") {
  using facet::test::filteredSize;
  for (const int interlace : {0, 1}) {
    CAPTURE(interlace);
    const std::uint64_t needed = filteredSize(4096, 4096, 8, 0, interlace);  // the bytes the data must inflate to
    // Not a valid stream (a stored block whose length check fails): past the bound, the decoder says so.
    const auto withData = [&](std::uint64_t n) {
      std::string data(n, '\0');
      data[0] = '\x78';
      data[1] = '\x01';
      return pngFile(ihdrChunk(4096, 4096, 8, 0, interlace) + pngChunk("IDAT", data));
    };
    const std::uint64_t tooFew = (needed - 1) / 1032;  // 1032 * tooFew < needed
    CHECK(refusal(withData(tooFew)) == "t.png: truncated or corrupt PNG: " + std::to_string(tooFew) +
                                           " bytes of compressed image data cannot hold 4096x4096 pixels");
    const std::string decoded = refusal(withData(tooFew + 1));
    CHECK(decoded.rfind("t.png: corrupt PNG image data", 0) == 0);
  }
}
