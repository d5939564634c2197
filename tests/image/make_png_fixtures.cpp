// Writes the broken and the very large PNGs that the `facet diff` tests of
// the PNG reader read (tests/image/CMakeLists.txt), into the folder given as
// the only argument (the build tree), so no binary file is committed.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "image/png.h"
#include "png_bytes.h"

using namespace facet;
using namespace facet::test;
namespace fs = std::filesystem;

namespace {

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_png_fixtures FOLDER\n");
    return 2;
  }
  const fs::path root = argv[1];
  try {
    fs::remove_all(root);
    fs::create_directories(root);
    const std::vector<std::uint8_t> written = encodePng(Image(10, 10, {10, 20, 40, 255}), "base.png");
    const std::string base(written.begin(), written.end());
    const std::size_t idat = base.find("IDAT") - 4;
    writeBytes(root / "base.png", base);

    std::string crc = base;
    crc[idat + 8] ^= 0x01;  // the first byte of the image data
    writeBytes(root / "crc_error.png", crc);
    writeBytes(root / "truncated.png", base.substr(0, idat + 12));  // into the image data
    writeBytes(root / "empty.png", "");
    writeBytes(root / "trailing.png", base + "trailing garbage");
    // 20000x20000 claimed by 48 KB: past the size limit.
    std::string noise(48 * 1024, '\0');
    for (std::size_t i = 0; i < noise.size(); ++i) noise[i] = static_cast<char>((i * 2654435761u) >> 13);
    writeBytes(root / "huge_claim.png", pngFile(ihdrChunk(20000, 20000) + pngChunk("IDAT", noise)));
    // A valid 16384x16384 RGBA file (1 GiB of pixels in 6.7 MB): within the
    // limit, so only memory can stop it.
    writeBytes(root / "big_zeros.png", zeroPng(16384, 16384, 8, 6, 0, true));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_png_fixtures: %s\n", e.what());
    return 1;
  }
  return 0;
}
