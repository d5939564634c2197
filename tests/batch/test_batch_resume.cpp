// --resume's parts: the inputs hash, and the PNG text chunk that carries it.
#include <doctest/doctest.h>

#include "image/png.h"
#include "image/png_text.h"
#include "inputs_hash.h"

namespace facet {

TEST_CASE("the inputs hash changes with each input, and fields do not run together") {
  const std::string base = inputsHash("scene", "{}", 64, 48, "cpu", "0.1.0");
  CHECK(base.size() == 16);
  CHECK(base == inputsHash("scene", "{}", 64, 48, "cpu", "0.1.0"));
  CHECK(base != inputsHash("scene!", "{}", 64, 48, "cpu", "0.1.0"));
  CHECK(base != inputsHash("scene", "{ }", 64, 48, "cpu", "0.1.0"));
  CHECK(base != inputsHash("scene", "{}", 48, 64, "cpu", "0.1.0"));
  CHECK(base != inputsHash("scene", "{}", 64, 48, "gl", "0.1.0"));
  CHECK(base != inputsHash("scene", "{}", 64, 48, "cpu", "0.1.1"));
  CHECK(inputsHash("ab", "c", 1, 1, "", "") != inputsHash("a", "bc", 1, 1, "", ""));
  Fnv1a64 empty;
  CHECK(empty.hex() == "cbf29ce484222325");  // FNV-1a's offset basis: the published constant
  Fnv1a64 a;
  a.add("a");
  CHECK(a.hex() == "af63dc4c8601ec8c");  // FNV-1a 64 of "a", the published test vector
}

TEST_CASE("a PNG text chunk: written before IEND, read back, and the image decodes as before") {
  Image image(3, 2);
  image.at(1, 1) = Rgba8{10, 20, 30, 255};
  const std::vector<std::uint8_t> plain = encodePng(image, "t.png");
  const std::vector<std::uint8_t> tagged = withTextChunk(plain, "facet-inputs", "0123abcd");
  const std::string_view bytes(reinterpret_cast<const char*>(tagged.data()), tagged.size());
  CHECK(textChunk(bytes, "facet-inputs") == "0123abcd");
  CHECK_FALSE(textChunk(bytes, "other"));
  CHECK_FALSE(textChunk(std::string_view(reinterpret_cast<const char*>(plain.data()), plain.size()), "facet-inputs"));
  const Image back = decodePng(bytes, "t.png");  // strict: CRCs and chunk order checked
  CHECK(back.at(1, 1).g == 20);
  CHECK_FALSE(textChunk("not a png at all", "facet-inputs"));
}

}  // namespace facet
