// Writes the small PNGs the `facet diff` command-line tests compare, into
// the folder given as the only argument (the build tree), so no binary file
// is committed. Every image is 10x10 unless its name says otherwise.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>

#include "common/error.h"
#include "image/png.h"
#include "test_images.h"

using namespace facet;
using namespace facet::test;
namespace fs = std::filesystem;

namespace {

void writeNotPng(const fs::path& path) { std::ofstream(path) << "this is not a PNG\n"; }

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_diff_fixtures FOLDER\n");
    return 2;
  }
  const fs::path root = argv[1];
  try {
    fs::remove_all(root);
    for (const char* sub : {"expected", "actual", "sizes_expected", "sizes_actual", "broken_expected", "broken_actual"})
      fs::create_directories(root / sub);
    const auto png = [&](const fs::path& relative, const Image& image) { writePng((root / relative).string(), image); };

    const Image base(10, 10, kSlate);
    const Image offByOne = withPixel(base, 3, 5, {11, 20, 40, 255});  // one step: warns
    const Image onePixel = withPixel(base, 3, 5, {20, 20, 40, 255});  // ten steps: fails; (3, 4) from the top
    const Image edge = objectImage(10, 10, 2, 5), edgeMoved = objectImage(10, 10, 2, 6);

    // Single files.
    png("base.png", base);
    png("same.png", base);
    png("off_by_one.png", offByOne);
    png("one_pixel.png", onePixel);
    png("shift2.png", shifted(base, 2));
    png("wide.png", Image(12, 10, kSlate));
    writeNotPng(root / "not_a.png");

    // Two folders: one case of each kind, and a file that is not an image.
    for (const auto& [name, expected, actual] : {std::tuple{"identical.png", base, base}, std::tuple{"off_by_one.png", base, offByOne},
                                                  std::tuple{"one_pixel.png", base, onePixel}, std::tuple{"edge.png", edge, edgeMoved}}) {
      png(fs::path("expected") / name, expected);
      png(fs::path("actual") / name, actual);
    }
    png("expected/only_expected.png", base);
    png("actual/only_actual.png", base);
    std::ofstream(root / "expected" / "notes.txt") << "not compared\n";

    // Folders whose worst case is a size mismatch, and an unreadable file.
    png("sizes_expected/a.png", base);
    png("sizes_actual/a.png", onePixel);
    png("sizes_expected/b.png", base);
    png("sizes_actual/b.png", Image(12, 10, kSlate));
    png("broken_expected/a.png", base);
    png("broken_actual/a.png", Image(12, 10, kSlate));
    png("broken_expected/b.png", base);
    writeNotPng(root / "broken_actual" / "b.png");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_diff_fixtures: %s\n", e.what());
    return 1;
  }
  return 0;
}
