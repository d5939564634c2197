// PNG read/write: rows flip once, round trips are exact, failures leave no file.
#include <filesystem>

#include <doctest/doctest.h>
#include <stb_image.h>

#include "common/error.h"
#include "image/png.h"

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
