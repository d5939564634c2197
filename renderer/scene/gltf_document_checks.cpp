#include "scene/gltf_document_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <vector>

#include "common/error.h"
#include "common/quote.h"
#include "scene/gltf_sampler.h"

namespace facet {
namespace {

using nlohmann::json;

std::string show(std::string_view text) { return quoteInput(text); }

const json& arrayOf(const json& object, const char* key) {
  static const json kEmpty = json::array();
  const auto it = object.find(key);
  return it != object.end() && it->is_array() ? *it : kEmpty;
}

// "nodes[7]", with the object's name when it has one: "nodes[7] 'wheel'".
std::string named(const char* array, std::size_t index, const json& object) {
  std::string name = std::string(array) + "[" + std::to_string(index) + "]";
  if (object.is_object())
    if (const auto it = object.find("name"); it != object.end() && it->is_string()) {
      name += ' ';
      name += show(it->get<std::string>());
    }
  return name;
}

std::string at(const char* array, std::size_t index) { return std::string(array) + "[" + std::to_string(index) + "]"; }

// "1 sampler", "3 samplers".

// An angle for a message: "-1 rad (-57.3 deg)".
std::string radians(double a) {
  char text[64];
  std::snprintf(text, sizeof text, "%g rad (%.3g deg)", a, a * 57.29577951308232);
  return text;
}

// A JSON value as glTF's "integer" with minimum 0; an integral float (4.0) counts.
bool nonNegativeInteger(const json& value, std::uint64_t& out) {
  if (value.is_number_unsigned()) {
    out = value.get<std::uint64_t>();
    return true;
  }
  if (value.is_number_integer()) return false;  // negative
  if (value.is_number_float()) {
    const double d = value.get<double>();
    if (!(d >= 0.0) || d >= 18446744073709551616.0 || std::floor(d) != d) return false;
    out = static_cast<std::uint64_t>(d);
    return true;
  }
  return false;
}

// An optional integer property; `fallback` when absent. Refuses anything
// but a non-negative integer, naming the object.
std::uint64_t integerProperty(const std::string& object, const json& o, const char* key, std::uint64_t fallback) {
  const auto it = o.find(key);
  if (it == o.end()) return fallback;
  std::uint64_t value = 0;
  if (!nonNegativeInteger(*it, value)) throw Error(object + ": " + key + " " + show(it->dump()) + " is not a non-negative integer");
  return value;
}

// glTF 2.0, 3.6.2 "Buffers and Buffer Views": a bufferView's bytes lie in
// its buffer (the glTF-Validator's BUFFER_VIEW_TOO_LONG). tinygltf hands an
// image's bufferView to the image callback as a pointer into the buffer
// without checking it, so an image's bufferView is checked here, before
// tinygltf runs; the bufferViews of accessors (sparse indices and values
// too) are checked where they are read (gltf_accessor.h), which skips the
// primitive with a warning.
void checkImageBufferViews(const json& document) {
  const json& buffers = arrayOf(document, "buffers");
  const json& views = arrayOf(document, "bufferViews");
  const json& images = arrayOf(document, "images");
  for (std::size_t i = 0; i < images.size(); ++i) {
    if (!images[i].is_object()) continue;  // tinygltf refuses it
    const auto bufferView = images[i].find("bufferView");
    if (bufferView == images[i].end()) continue;
    const std::string image = named("images", i, images[i]);
    std::uint64_t v = 0;
    if (!nonNegativeInteger(*bufferView, v) || v >= views.size() || !views[static_cast<std::size_t>(v)].is_object())
      throw Error(image + ": bufferView " + show(bufferView->dump()) + " does not exist (UNRESOLVED_REFERENCE: the file has " +
                  countOf(views.size(), "bufferView") + ")");
    const json& view = views[static_cast<std::size_t>(v)];
    const std::string name = image + ": " + named("bufferViews", static_cast<std::size_t>(v), view);
    const auto buffer = view.find("buffer");
    std::uint64_t b = 0;
    if (buffer == view.end() || !nonNegativeInteger(*buffer, b) || b >= buffers.size() || !buffers[static_cast<std::size_t>(b)].is_object())
      throw Error(name + ": buffer " + (buffer == view.end() ? std::string("is missing") : show(buffer->dump()) + " does not exist") +
                  " (UNRESOLVED_REFERENCE: the file has " + countOf(buffers.size(), "buffer") + ")");
    const std::string bufferName = named("buffers", static_cast<std::size_t>(b), buffers[static_cast<std::size_t>(b)]);
    const std::uint64_t size = integerProperty(bufferName, buffers[static_cast<std::size_t>(b)], "byteLength", 0);
    const std::uint64_t offset = integerProperty(name, view, "byteOffset", 0);
    const std::uint64_t length = integerProperty(name, view, "byteLength", 0);
    if (length == 0) throw Error(name + ": byteLength must be 1 or more");
    if (offset > size || length > size - offset)  // overflow-safe offset + length > size
      throw Error(name + ": byteOffset " + std::to_string(offset) + " + byteLength " + std::to_string(length) + " runs past the end of " +
                  at("buffers", static_cast<std::size_t>(b)) + ", which has " + std::to_string(size) + " bytes (BUFFER_VIEW_TOO_LONG)");
  }
}

// The file a relative URI names, decoded as tinygltf decodes it (%XX, and
// '+' as a space): glTF 2.0, 2.8 "URIs" resolve relative to the glTF file.
std::string decodeUri(const std::string& uri) {
  const auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return 0;
  };
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && i + 2 < uri.size()) {
      out += static_cast<char>(hex(uri[i + 1]) << 4 | hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// A buffer's external file: it exists, is a regular file, lies inside the
// scene's folder (symbolic links resolved) and is not larger than the
// largest file facet reads. tinygltf itself would say "File not found" for
// all of these, and search the current directory too.
void checkBufferUris(const json& document, const std::string& folder, std::uint64_t maxFileBytes) {
  namespace fs = std::filesystem;
  const json& buffers = arrayOf(document, "buffers");
  for (std::size_t b = 0; b < buffers.size(); ++b) {
    if (!buffers[b].is_object()) continue;
    const auto uri = buffers[b].find("uri");
    if (uri == buffers[b].end() || !uri->is_string()) continue;
    const std::string text = uri->get<std::string>();
    if (text.rfind("data:", 0) == 0) continue;  // embedded; tinygltf decodes and size-checks it
    const std::string name = named("buffers", b, buffers[b]) + ": uri " + show(text);
    if (folder.empty()) throw Error(name + ": external files are not read for a scene given as bytes");
    const std::string decoded = decodeUri(text);
    const fs::path file = fs::path(decoded).is_absolute() ? fs::path(decoded) : fs::path(folder) / decoded;
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (ec || !fs::exists(status)) throw Error(name + ": no such file");
    if (!fs::is_regular_file(status)) throw Error(name + ": not a regular file");
    const fs::path canonical = fs::weakly_canonical(file, ec);
    const fs::path root(folder);
    const auto [rootEnd, unused] = std::mismatch(root.begin(), root.end(), canonical.begin(), canonical.end());
    (void)unused;
    if (ec || rootEnd != root.end()) throw Error(name + ": outside the scene's folder, where facet reads no files");
    const std::uint64_t size = fs::file_size(file, ec);
    if (!ec && size > maxFileBytes)
      throw Error(name + ": file is " + std::to_string(size) + " bytes, more than the limit of " + std::to_string(maxFileBytes));
  }
}

// glTF 2.0, 3.5.3 "Transformations": "the node hierarchy MUST be a set of
// disjoint strict trees. That is node hierarchy MUST NOT contain cycles and
// each node MUST have zero or one parent node"; 3.5.2: scene nodes "MUST be
// root nodes". A node listed as a child twice would be drawn once per path
// to it: 2^40 times for 41 nodes. Refused at once, naming the node.
void checkNodeHierarchy(const json& document) {
  const json& nodes = arrayOf(document, "nodes");
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> parent(nodes.size(), kNone);
  const auto node = [&](std::size_t n) { return named("nodes", n, nodes[n]); };
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    if (!nodes[n].is_object()) continue;
    for (const json& child : arrayOf(nodes[n], "children")) {
      std::uint64_t c = 0;
      if (!nonNegativeInteger(child, c) || c >= nodes.size()) continue;  // the walker warns of it (UNRESOLVED_REFERENCE)
      const auto k = static_cast<std::size_t>(c);
      if (k == n) throw Error(node(k) + ": is its own child (NODE_LOOP: glTF node hierarchies are trees)");
      if (parent[k] == n) throw Error(node(k) + ": is listed twice among the children of " + at("nodes", n) + " (ARRAY_DUPLICATE_ELEMENTS)");
      if (parent[k] != kNone)
        throw Error(node(k) + ": is a child of both " + at("nodes", parent[k]) + " and " + at("nodes", n) +
                    ", but a glTF node has at most one parent (NODE_PARENT_OVERRIDE)");
      parent[k] = n;
    }
  }
  // With one parent each, a loop is a chain of parents that never reaches a
  // root. state: 0 unvisited, 1 on the chain being followed, 2 known to reach a root.
  std::vector<char> state(nodes.size(), 0);
  std::vector<std::size_t> chain;
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    chain.clear();
    std::size_t k = n;
    while (k != kNone && state[k] == 0) {
      state[k] = 1;
      chain.push_back(k);
      k = parent[k];
    }
    if (k != kNone && state[k] == 1) throw Error(node(k) + ": is its own ancestor (NODE_LOOP: glTF node hierarchies are trees)");
    for (std::size_t c : chain) state[c] = 2;
  }
  const json& scenes = arrayOf(document, "scenes");
  for (std::size_t s = 0; s < scenes.size(); ++s) {
    if (!scenes[s].is_object()) continue;
    std::vector<char> listed(nodes.size(), 0);
    for (const json& root : arrayOf(scenes[s], "nodes")) {
      std::uint64_t r = 0;
      if (!nonNegativeInteger(root, r) || r >= nodes.size()) continue;
      const auto k = static_cast<std::size_t>(r);
      if (parent[k] != kNone)
        throw Error(named("scenes", s, scenes[s]) + ": " + node(k) + " is a root of the scene but a child of " + at("nodes", parent[k]) +
                    " (SCENE_NON_ROOT_NODE)");
      if (listed[k]) throw Error(named("scenes", s, scenes[s]) + ": lists " + node(k) + " twice (ARRAY_DUPLICATE_ELEMENTS)");
      listed[k] = 1;
    }
  }
}

// glTF 2.0, 5.29 "texture.sampler": the index of a sampler that exists.
// facet samples with REPEAT and no filter choice either way, but a
// reference to nothing is a broken file, not a default.
void checkTextureSamplers(const json& document) {
  const json& textures = arrayOf(document, "textures");
  const std::size_t samplers = arrayOf(document, "samplers").size();
  for (std::size_t t = 0; t < textures.size(); ++t) {
    if (!textures[t].is_object()) continue;
    const auto sampler = textures[t].find("sampler");
    if (sampler == textures[t].end()) continue;  // "When undefined, a sampler with repeat wrapping and auto filtering MUST be used"
    std::uint64_t s = 0;
    if (!nonNegativeInteger(*sampler, s) || s >= samplers)
      throw Error(named("textures", t, textures[t]) + ": sampler " + show(sampler->dump()) + " does not exist (UNRESOLVED_REFERENCE: the file has " +
                  countOf(samplers, "sampler") + ")");
  }
}

// glTF 2.0, 5.26 "sampler": magFilter, minFilter, wrapS and wrapT are GL
// enums from short lists; another number is a broken file, named here,
// rather than a filter quietly chosen for it.
template <std::size_t N>
void checkSamplerKey(const json& sampler, const std::string& name, const char* key, const std::array<GlEnum, N>& codes) {
  const auto it = sampler.find(key);
  if (it == sampler.end()) return;
  std::uint64_t value = 0;
  if (nonNegativeInteger(*it, value) && value < 65536 && enumIndex(codes, static_cast<long long>(value))) return;
  std::string allowed;
  for (const GlEnum& e : codes) allowed += (allowed.empty() ? "" : ", ") + std::string(e.name) + " (" + std::to_string(e.code) + ")";
  throw Error(name + ": " + key + " " + show(it->dump()) + " is not one of " + allowed);
}

void checkSamplers(const json& document) {
  const json& samplers = arrayOf(document, "samplers");
  for (std::size_t i = 0; i < samplers.size(); ++i) {
    if (!samplers[i].is_object()) continue;
    const std::string name = named("samplers", i, samplers[i]);
    checkSamplerKey(samplers[i], name, "magFilter", kMagFilterCodes);
    checkSamplerKey(samplers[i], name, "minFilter", kMinFilterCodes);
    checkSamplerKey(samplers[i], name, "wrapS", kWrapCodes);
    checkSamplerKey(samplers[i], name, "wrapT", kWrapCodes);
  }
}

// glTF 2.0, 5.23 "textureInfo.index": a material's texture (base colour,
// metallic-roughness, normal, occlusion, emissive) is one that exists; and
// its alphaMode is one of glTF's three, its alphaCutoff a number ≥ 0.
void checkMaterialTextures(const json& document) {
  const json& materials = arrayOf(document, "materials");
  const std::size_t textures = arrayOf(document, "textures").size();
  const auto check = [&](std::size_t m, const json& owner, const char* key, const std::string& path) {
    if (!owner.is_object()) return;
    const auto info = owner.find(key);
    if (info == owner.end() || !info->is_object()) return;
    const auto index = info->find("index");
    std::uint64_t t = 0;
    if (index == info->end())
      throw Error(named("materials", m, materials[m]) + ": " + path + " has no index");
    if (!nonNegativeInteger(*index, t) || t >= textures)
      throw Error(named("materials", m, materials[m]) + ": " + path + ".index " + show(index->dump()) +
                  " does not exist (UNRESOLVED_REFERENCE: the file has " + countOf(textures, "texture") + ")");
  };
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const json& material = materials[m];
    if (!material.is_object()) continue;
    // glTF 2.0, 5.19 "material.alphaMode" and "alphaCutoff" (minimum 0).
    if (const auto mode = material.find("alphaMode"); mode != material.end()) {
      const std::string text = mode->is_string() ? mode->get<std::string>() : "";
      if (text != "OPAQUE" && text != "MASK" && text != "BLEND")
        throw Error(named("materials", m, material) + ": alphaMode " + show(mode->dump()) + " is not one of OPAQUE, MASK, BLEND");
    }
    if (const auto cutoff = material.find("alphaCutoff"); cutoff != material.end()) {
      if (!cutoff->is_number() || !(cutoff->get<double>() >= 0.0) || !std::isfinite(cutoff->get<double>()))
        throw Error(named("materials", m, material) + ": alphaCutoff " + show(cutoff->dump()) + " is not a finite number of at least 0");
    }
    if (const auto pbr = material.find("pbrMetallicRoughness"); pbr != material.end()) {
      check(m, *pbr, "baseColorTexture", "pbrMetallicRoughness.baseColorTexture");
      check(m, *pbr, "metallicRoughnessTexture", "pbrMetallicRoughness.metallicRoughnessTexture");
    }
    for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"}) check(m, material, key, key);
  }
}

// KHR_lights_punctual: "type" is one of directional, point, spot; a spot
// light has a "spot" object whose angles satisfy
// 0 ≤ innerConeAngle < outerConeAngle ≤ π/2 (defaults 0 and π/4).
void checkLights(const json& document) {
  const auto extensions = document.find("extensions");
  if (extensions == document.end() || !extensions->is_object()) return;
  const auto punctual = extensions->find("KHR_lights_punctual");
  if (punctual == extensions->end() || !punctual->is_object()) return;
  const json& lights = arrayOf(*punctual, "lights");
  constexpr double kHalfPi = 1.57079632679489661923;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    const std::string name = "KHR_lights_punctual " + named("lights", l, lights[l]);
    if (!lights[l].is_object()) throw Error(name + ": is not a JSON object");
    const auto type = lights[l].find("type");
    if (type == lights[l].end()) throw Error(name + ": has no type (one of directional, point, spot)");
    if (!type->is_string() || (*type != "directional" && *type != "point" && *type != "spot"))
      throw Error(name + ": type " + show(type->is_string() ? type->get<std::string>() : type->dump()) +
                  " is not one of directional, point, spot");
    if (*type != "spot") continue;
    const auto spot = lights[l].find("spot");
    if (spot == lights[l].end() || !spot->is_object()) throw Error(name + ": a spot light needs its spot object (innerConeAngle, outerConeAngle)");
    const auto angle = [&](const char* key, double fallback) {
      const auto it = spot->find(key);
      if (it == spot->end()) return fallback;
      if (!it->is_number() || !std::isfinite(it->get<double>())) throw Error(name + ": spot." + key + " " + show(it->dump()) + " is not a finite number");
      return it->get<double>();
    };
    const double inner = angle("innerConeAngle", 0.0), outer = angle("outerConeAngle", kHalfPi / 2);
    if (!(inner >= 0.0 && inner < outer && outer <= kHalfPi))
      throw Error(name + ": spot.innerConeAngle " + radians(inner) + " and outerConeAngle " + radians(outer) +
                  " break 0 <= innerConeAngle < outerConeAngle <= pi/2");
  }
}

// A JSON value's kind for a message: "\"hello\"" is a string, and so on.
std::string valueOf(const json& value) { return show(value.dump()); }

// Every "extensions" member below `value` (not inside "extras", which is the
// application's) is an object of objects, as glTF 2.0's extension.schema.json
// says: an extension read as something else would be read as absent.
void checkExtensionObjects(const json& value, const std::string& path, int depth) {
  if (depth > 8) return;  // glTF nests extensions at most a few levels down
  if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      if (value[i].is_object() || value[i].is_array()) checkExtensionObjects(value[i], path + "[" + std::to_string(i) + "]", depth + 1);
    return;
  }
  if (!value.is_object()) return;
  for (const auto& [key, member] : value.items()) {
    if (key == "extras") continue;
    const std::string at = path.empty() ? key : path + "." + key;
    if (key == "extensions") {
      if (!member.is_object()) throw Error(at + " " + valueOf(member) + " is not a JSON object");
      for (const auto& [name, extension] : member.items())
        if (!extension.is_object()) throw Error(at + "." + show(name) + " " + valueOf(extension) + " is not a JSON object");
    }
    checkExtensionObjects(member, at, depth + 1);
  }
}

// glTF 2.0's JSON schema for what facet reads: the top-level arrays are arrays
// of objects with string names, "scene" names a scene that exists, a mesh has
// an array of primitives with an attributes object, and a material's
// pbrMetallicRoughness and texture references are objects and its factors
// numbers. A value of the wrong type is a broken file (assimp's wrongTypes
// models), refused by name, rather than read as if it were absent.
void checkSchemaTypes(const json& document) {
  static constexpr const char* kArrays[] = {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials",
                                            "meshes",    "nodes",      "samplers", "scenes",      "skins",   "textures"};
  for (const char* key : kArrays) {
    const auto it = document.find(key);
    if (it == document.end()) continue;
    if (!it->is_array()) throw Error(std::string(key) + " " + valueOf(*it) + " is not an array");
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json& object = (*it)[i];
      if (!object.is_object()) throw Error(at(key, i) + " " + valueOf(object) + " is not a JSON object");
      if (const auto name = object.find("name"); name != object.end() && !name->is_string())
        throw Error(at(key, i) + ": name " + valueOf(*name) + " is not a string");
    }
  }
  if (const auto scene = document.find("scene"); scene != document.end()) {
    const std::size_t scenes = arrayOf(document, "scenes").size();
    std::uint64_t index = 0;
    if (!nonNegativeInteger(*scene, index) || index >= scenes)
      throw Error("scene " + valueOf(*scene) + " does not exist (UNRESOLVED_REFERENCE: the file has " + countOf(scenes, "scene") + ")");
  }
  const json& meshes = arrayOf(document, "meshes");
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const std::string mesh = named("meshes", m, meshes[m]);
    const auto primitives = meshes[m].find("primitives");
    if (primitives == meshes[m].end() || !primitives->is_array() || primitives->empty())
      throw Error(mesh + ": primitives " + (primitives == meshes[m].end() ? std::string("is missing") : valueOf(*primitives) + " is not") +
                  " an array of one or more primitives");
    for (std::size_t p = 0; p < primitives->size(); ++p) {
      const json& primitive = (*primitives)[p];
      const std::string name = mesh + ": " + at("primitives", p);
      if (!primitive.is_object()) throw Error(name + " " + valueOf(primitive) + " is not a JSON object");
      const auto attributes = primitive.find("attributes");
      if (attributes == primitive.end() || !attributes->is_object())
        throw Error(name + ": attributes " + (attributes == primitive.end() ? std::string("is missing") : valueOf(*attributes) + " is not a JSON object"));
    }
  }
  const json& materials = arrayOf(document, "materials");
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const json& material = materials[m];
    const std::string name = named("materials", m, material);
    const auto expect = [&](const json& owner, const char* key, const std::string& path, bool (json::*is)() const noexcept, const char* kind) {
      const auto it = owner.find(key);
      if (it != owner.end() && !((*it).*is)()) throw Error(name + ": " + path + " " + valueOf(*it) + " is not " + kind);
    };
    const auto textureInfo = [&](const json& owner, const char* key, const std::string& path) {
      expect(owner, key, path, &json::is_object, "a JSON object");
      if (const auto info = owner.find(key); info != owner.end()) {
        expect(*info, "texCoord", path + ".texCoord", &json::is_number_integer, "an integer");
        expect(*info, "scale", path + ".scale", &json::is_number, "a number");
        expect(*info, "strength", path + ".strength", &json::is_number, "a number");
      }
    };
    expect(material, "pbrMetallicRoughness", "pbrMetallicRoughness", &json::is_object, "a JSON object");
    if (const auto pbr = material.find("pbrMetallicRoughness"); pbr != material.end()) {
      expect(*pbr, "baseColorFactor", "pbrMetallicRoughness.baseColorFactor", &json::is_array, "an array of numbers");
      expect(*pbr, "metallicFactor", "pbrMetallicRoughness.metallicFactor", &json::is_number, "a number");
      expect(*pbr, "roughnessFactor", "pbrMetallicRoughness.roughnessFactor", &json::is_number, "a number");
      textureInfo(*pbr, "baseColorTexture", "pbrMetallicRoughness.baseColorTexture");
      textureInfo(*pbr, "metallicRoughnessTexture", "pbrMetallicRoughness.metallicRoughnessTexture");
    }
    expect(material, "emissiveFactor", "emissiveFactor", &json::is_array, "an array of numbers");
    expect(material, "doubleSided", "doubleSided", &json::is_boolean, "true or false");
    for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"}) textureInfo(material, key, key);
  }
  checkExtensionObjects(document, "", 0);
}

}  // namespace

void checkGltfDocument(const std::string& path, const nlohmann::json& document, const std::string& folder, std::uint64_t maxFileBytes) {
  try {
    checkSchemaTypes(document);
    checkImageBufferViews(document);
    checkBufferUris(document, folder, maxFileBytes);
    checkNodeHierarchy(document);
    checkTextureSamplers(document);
    checkSamplers(document);
    checkMaterialTextures(document);
    checkLights(document);
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
}

}  // namespace facet
