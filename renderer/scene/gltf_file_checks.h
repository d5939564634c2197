#pragma once
// What a glTF file's bytes must be before any JSON parser reads them:
// UTF-8 JSON text (glTF 2.0, section 3.2), or a GLB whose header and chunks
// add up (section 4.4, "Binary glTF Layout"). A file that is something else
// is refused with one line saying what it is ("is a PNG image, not a glTF
// file"), never with a parser's echo of its raw bytes.
#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace facet {

// Where a file's JSON text and binary chunk are.
struct GltfLayout {
  bool binary = false;                          // a GLB
  std::size_t jsonOffset = 0, jsonLength = 0;   // the JSON text: the whole .gltf, or the GLB's JSON chunk
  bool hasBin = false;
  std::size_t binOffset = 0, binLength = 0;     // the GLB's BIN chunk data
  // Only the header, the JSON chunk and a BIN chunk right after it: tinygltf
  // reads such a GLB as it is; another (with chunks of unknown types, which
  // glTF says to ignore) is handed to it rebuilt.
  bool plain = true;
};

// The layout of `bytes`, read from the file `path` (named in messages).
// Throws facet::Error when they are not a glTF file: another kind of file
// (PNG, JPEG, ZIP, ...), JSON text in UTF-16 or UTF-32, JSON text holding a
// NUL byte, or a GLB whose header or chunks are malformed (named with the
// glTF-Validator's GLB_* codes). `glbByName`: the file is called .glb, so
// bytes without GLB's magic are reported as a bad GLB header.
GltfLayout gltfLayout(const std::string& path, std::string_view bytes, bool glbByName);

// A GLB of the JSON text `json` (padded with spaces) and the BIN chunk `bin`
// (none when empty): what tinygltf is given when the document or the chunk
// layout had to change.
std::string glbBytes(std::string json, std::string_view bin);

// The JSON document of a glTF file. Throws facet::Error naming `path`, the
// line and column and what is wrong, with the offending text quoted
// (common/quote.h), for text that is not JSON or not a JSON object.
nlohmann::json parseGltfJson(const std::string& path, std::string_view text);

}  // namespace facet
