#include "scene/gltf_file_checks.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "common/error.h"
#include "common/quote.h"

namespace facet {
namespace {

std::string show(std::string_view text) { return quoteInput(text); }

constexpr std::uint32_t kJsonChunk = 0x4E4F534Au;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942u;   // "BIN\0"

std::uint32_t u32(std::string_view bytes, std::size_t offset) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + offset, 4);
  return v;  // GLB is little-endian, as is every machine facet builds for
}

bool startsWith(std::string_view bytes, std::string_view prefix) { return bytes.substr(0, prefix.size()) == prefix; }

// Files people pass for a scene by mistake, by their magic bytes.
struct Magic {
  std::string_view bytes;
  const char* what;
};
constexpr Magic kOtherFormats[] = {
    {std::string_view("\x89PNG\r\n\x1a\n", 8), "a PNG image"},
    {std::string_view("\xff\xd8\xff", 3), "a JPEG image"},
    {"GIF8", "a GIF image"},
    {std::string_view("\xabKTX 20\xbb", 8), "a KTX2 texture"},
    {"DDS ", "a DDS texture"},
    {std::string_view("PK\x03\x04", 4), "a ZIP archive"},
    {std::string_view("\x1f\x8b", 2), "a gzip file"},
    {"%PDF", "a PDF document"},
    {"Kaydara FBX Binary", "an FBX file"},
    {std::string_view("\x7f" "ELF", 4), "an ELF executable"},
};

// "UTF-16LE" when the text is UTF-16 or UTF-32, by its byte-order mark or
// by the zero bytes around its first character (JSON starts with ASCII).
const char* wideEncoding(std::string_view b) {
  const auto at = [&](std::size_t i) { return i < b.size() ? static_cast<unsigned char>(b[i]) : 0x100u; };
  if (at(0) == 0xff && at(1) == 0xfe && at(2) == 0 && at(3) == 0) return "UTF-32LE";
  if (at(0) == 0 && at(1) == 0 && at(2) == 0xfe && at(3) == 0xff) return "UTF-32BE";
  if (at(0) == 0xff && at(1) == 0xfe) return "UTF-16LE";
  if (at(0) == 0xfe && at(1) == 0xff) return "UTF-16BE";
  if (at(0) != 0 && at(0) < 0x80 && at(1) == 0 && at(2) == 0 && at(3) == 0) return "UTF-32LE";
  if (at(0) == 0 && at(1) == 0 && at(2) == 0 && at(3) != 0 && at(3) < 0x80) return "UTF-32BE";
  if (at(0) != 0 && at(0) < 0x80 && at(1) == 0) return "UTF-16LE";
  if (at(0) == 0 && at(1) != 0 && at(1) < 0x80) return "UTF-16BE";
  return nullptr;
}

// glTF 2.0, 3.2: "JSON must use UTF-8 encoding". Checked on the JSON text
// of a .gltf or of a GLB's JSON chunk (`where` names which).
void checkJsonText(const std::string& path, std::string_view text, const char* where) {
  if (const char* wide = wideEncoding(text))
    throw Error(path + ": not a glTF file (" + where + " must be UTF-8 JSON, and this is " + wide + " text)");
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos)
    throw Error(path + ": a NUL byte at byte " + std::to_string(nul) + " of the " + where +
                ", where JSON text cannot hold one (glTF JSON is UTF-8 text)");
  std::string_view rest = text;
  if (startsWith(rest, "\xef\xbb\xbf")) rest.remove_prefix(3);  // a UTF-8 byte-order mark: JSON parsers skip it
  const std::size_t first = rest.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos)
    throw Error(path + ": not a glTF file (" + where + (text.empty() ? " is empty)" : " holds only white space)"));
  if (rest[first] != '{')
    throw Error(path + ": not a glTF file (" + where + " must be UTF-8 JSON holding an object, and it starts with " +
                show(rest.substr(first, 16)) + ")");
}

std::string chunkName(std::uint32_t type) {
  if (type == kJsonChunk) return "JSON chunk";
  if (type == kBinChunk) return "BIN chunk";
  char text[32];
  std::snprintf(text, sizeof text, "chunk of type 0x%08x", static_cast<unsigned>(type));
  return text;
}

// glTF 2.0, 4.4: a 12-byte header (magic, version 2, total length), then
// chunks of an 8-byte header (length, type) and `length` bytes of data, each
// starting and ending on a 4-byte boundary; the JSON chunk first, at most
// one BIN chunk and only second; chunks of other types are ignored.
GltfLayout glbLayout(const std::string& path, std::string_view bytes) {
  const std::string glb = path + ": GLB ";
  if (bytes.substr(0, 4) != std::string_view("glTF").substr(0, std::min<std::size_t>(bytes.size(), 4)))
    throw Error(path + ": not a GLB file: it starts with " + show(bytes.substr(0, 4)) + ", not 'glTF' (GLB_INVALID_MAGIC)");
  if (bytes.size() < 12)
    throw Error(glb + "file of " + std::to_string(bytes.size()) + " bytes is shorter than its 12-byte header (GLB_UNEXPECTED_END_OF_HEADER)");
  if (u32(bytes, 4) != 2) throw Error(glb + "version " + std::to_string(u32(bytes, 4)) + " is not 2 (GLB_INVALID_VERSION)");
  const std::uint64_t length = u32(bytes, 8);
  if (length != bytes.size())
    throw Error(glb + "header declares " + std::to_string(length) + " bytes, but the file has " + std::to_string(bytes.size()) +
                " (GLB_LENGTH_MISMATCH)");
  GltfLayout layout;
  layout.binary = true;
  bool hasJson = false;
  int chunks = 0;
  for (std::uint64_t at = 12; at < length; ++chunks) {
    if (length - at < 8)
      throw Error(glb + "file ends " + std::to_string(length - at) + " bytes after byte " + std::to_string(at) +
                  ", too few for a chunk header of 8 (GLB_UNEXPECTED_END_OF_CHUNK_HEADER)");
    const std::uint64_t chunkLength = u32(bytes, at);
    const std::uint32_t type = u32(bytes, at + 4);
    const std::string chunk = chunkName(type) + " at byte " + std::to_string(at);
    if (chunkLength > length - at - 8)
      throw Error(glb + chunk + " declares " + std::to_string(chunkLength) + " bytes, but the file ends " + std::to_string(length - at - 8) +
                  " bytes after its header (GLB_CHUNK_TOO_BIG)");
    if (chunkLength % 4 != 0)
      throw Error(glb + chunk + " is " + std::to_string(chunkLength) +
                  " bytes long, not a multiple of 4: chunks are padded to 4-byte boundaries (GLB_CHUNK_LENGTH_UNALIGNED)");
    if (chunks == 0 && type != kJsonChunk) throw Error(glb + "first chunk is a " + chunk + ", not the JSON chunk (GLB_UNEXPECTED_FIRST_CHUNK)");
    if (type == kJsonChunk) {
      if (hasJson) throw Error(glb + "has a second " + chunk + " (GLB_DUPLICATE_CHUNK)");
      if (chunkLength == 0) throw Error(glb + chunk + " is empty (GLB_EMPTY_CHUNK)");
      hasJson = true;
      layout.jsonOffset = static_cast<std::size_t>(at + 8);
      layout.jsonLength = static_cast<std::size_t>(chunkLength);
    } else if (type == kBinChunk) {
      if (layout.hasBin) throw Error(glb + "has a second " + chunk + " (GLB_DUPLICATE_CHUNK)");
      if (chunks != 1) throw Error(glb + chunk + " is not the second chunk (GLB_UNEXPECTED_BIN_CHUNK)");
      if (chunkLength == 0) throw Error(glb + chunk + " is empty (GLB_EMPTY_CHUNK)");
      layout.hasBin = true;
      layout.binOffset = static_cast<std::size_t>(at + 8);
      layout.binLength = static_cast<std::size_t>(chunkLength);
    } else {
      layout.plain = false;  // glTF: "Client implementations MUST ignore chunks with unknown types"
    }
    at += 8 + chunkLength;
  }
  if (!hasJson) throw Error(glb + "file of " + std::to_string(length) + " bytes has no JSON chunk (GLB_UNEXPECTED_END_OF_CHUNK_HEADER)");
  // Spaces pad the JSON chunk (4.4.3.1); a JSON parser skips them as white space.
  checkJsonText(path, bytes.substr(layout.jsonOffset, layout.jsonLength), "GLB's JSON chunk");
  return layout;
}

}  // namespace

GltfLayout gltfLayout(const std::string& path, std::string_view bytes, bool glbByName) {
  for (const Magic& magic : kOtherFormats)
    if (startsWith(bytes, magic.bytes)) throw Error(path + ": is " + magic.what + ", not a glTF file");
  if (glbByName || startsWith(bytes, "glTF")) return glbLayout(path, bytes);
  checkJsonText(path, bytes, ".gltf");
  GltfLayout layout;
  layout.jsonLength = bytes.size();
  return layout;
}

std::string glbBytes(std::string json, std::string_view bin) {
  while (json.size() % 4 != 0) json.push_back(' ');
  std::string out = "glTF";
  const auto put32 = [&](std::uint64_t v) {
    const auto v32 = static_cast<std::uint32_t>(v);
    out.append(reinterpret_cast<const char*>(&v32), 4);
  };
  const std::size_t paddedBin = (bin.size() + 3) & ~std::size_t{3};
  put32(2);
  put32(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + paddedBin));
  put32(json.size());
  put32(kJsonChunk);
  out += json;
  if (!bin.empty()) {
    put32(paddedBin);
    put32(kBinChunk);
    out += bin;
    out.append(paddedBin - bin.size(), '\0');
  }
  return out;
}

nlohmann::json parseGltfJson(const std::string& path, std::string_view text) {
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::parse_error& e) {
    // e.what(): "[json.exception.parse_error.101] parse error at line 3, column 7: syntax error while parsing
    // value - invalid literal; last read: '<raw bytes>'; expected ...". Its words are kept, its raw bytes are
    // replaced by a quoted excerpt of the text.
    std::string what = e.what();
    const std::size_t at = what.find("parse error at ");
    if (at != std::string::npos) what = what.substr(at + std::strlen("parse error at "));
    std::string expected;
    if (const std::size_t read = what.find("; last read: '"); read != std::string::npos) {
      const std::size_t expect = what.find("'; expected ", read);
      if (expect != std::string::npos) expected = "," + what.substr(expect + 2);  // ", expected ...": one clause, no ';' 
      what = what.substr(0, read);
    }
    const std::size_t byte = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    const std::size_t from = byte > 12 ? byte - 12 : 0;
    throw Error(path + ": not valid JSON at " + what + expected + ", near " + show(text.substr(from, byte - from + 12)));
  } catch (const nlohmann::json::exception& e) {
    // e.g. out_of_range.406 "number overflow parsing '1e999'": its words, the literal quoted.
    std::string what = e.what();
    if (const std::size_t id = what.find("] "); id != std::string::npos) what = what.substr(id + 2);
    if (const std::size_t open = what.find(" '"); open != std::string::npos && what.back() == '\'')
      what = what.substr(0, open + 1) + show(std::string_view(what).substr(open + 2, what.size() - open - 3));
    throw Error(path + ": not valid JSON: " + what);
  }
  if (!document.is_object()) throw Error(path + ": not a glTF file (its JSON is " + std::string(document.type_name()) + ", not an object)");
  return document;
}

}  // namespace facet
