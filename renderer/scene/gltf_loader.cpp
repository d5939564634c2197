// Index of this file
// [SECTION] Limits
// [SECTION] JSON nesting
// [SECTION] Callbacks that keep tinygltf inside the asset's folder and check images
// [SECTION] Materials and textures
// [SECTION] Primitives to meshes
// [SECTION] Nodes: world transforms, instances, cameras, lights
// [SECTION] loadGltf
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <stb_image.h>
#include <tiny_gltf.h>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/json_text.h"
#include "common/quote.h"
#include "image/mipmap.h"
#include "math/transforms.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_document_checks.h"
#include "scene/gltf_file_checks.h"
#include "scene/gltf_sampler.h"
#include "scene/memory_budget.h"
#include "scene/vertex_normals.h"
#include "scene/vertex_tangents.h"
#include "settings/settings_json.h"
#include "settings/render_settings.h"
#include "vocabulary/limits.h"

namespace facet {
namespace {

using Warnings = std::vector<std::string>;

std::string at(const char* array, std::size_t index) { return std::string(array) + "[" + std::to_string(index) + "]"; }

// [SECTION] JSON nesting

// Deepest nesting of objects and arrays in JSON text (strings skipped).
// tinygltf's JSON parser recurses, so a deeply nested file would overflow the stack.
int jsonDepth(const char* text, std::size_t length) {
  int depth = 0, deepest = 0;
  bool inString = false;
  for (std::size_t i = 0; i < length; ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      deepest = std::max(deepest, ++depth);
      if (deepest > kMaxGltfJsonDepth) return deepest;
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  return deepest;
}

// [SECTION] Callbacks that keep tinygltf inside the asset's folder and check images

struct AssetFolder {
  std::filesystem::path root;  // canonical folder of the .gltf/.glb
  std::vector<std::string> read;  // the files read from it (buffers, images), in order
};

// Whether a file is there at all: readWholeFile then says why it will not
// read one that is not a regular file or lies outside the folder (with
// is_regular_file here, tinygltf would report "File not found").
bool fileExists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

std::string expandFilePath(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  namespace fs = std::filesystem;
  auto* folder = static_cast<AssetFolder*>(user);
  if (folder->root.empty()) {
    if (err) *err += quoteInput(path) + ": external files are not read here\n";
    return false;
  }
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(path, ec);
  const auto [rootEnd, unused] = std::mismatch(folder->root.begin(), folder->root.end(), canonical.begin(), canonical.end());
  (void)unused;
  if (ec || rootEnd != folder->root.end()) {
    if (err) *err += quoteInput(path) + " is outside the asset's folder\n";
    return false;
  }
  try {
    const std::string bytes = readFile(canonical.string(), kMaxGltfFileBytes);
    out->assign(bytes.begin(), bytes.end());
    folder->read.push_back(canonical.string());
    return true;
  } catch (const Error& e) {
    if (err) *err += std::string(e.what()) + "\n";
    return false;
  }
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "facet never writes glTF files\n";
  return false;
}

// tinygltf 2.9 (Debian 13) asks a file's size before it reads the file, to
// hold it to its own limit; readWholeFile holds it to kMaxGltfFileBytes and
// names the problem, so this answers 0 and lets that one check decide.
[[maybe_unused]] bool fileSizeInBytes(std::size_t* size, std::string*, const std::string&, void*) {
  *size = 0;
  return true;
}

// The callbacks by member name: tinygltf 2.9 added GetFileSizeInBytes (and
// refuses a null one), which 2.7 (Debian 12) does not have.
template <typename Callbacks>
Callbacks folderCallbacks(AssetFolder& folder) {
  Callbacks c{};
  c.FileExists = fileExists;
  c.ExpandFilePath = expandFilePath;
  c.ReadWholeFile = readWholeFile;
  c.WriteWholeFile = refuseWrite;
  if constexpr (requires { c.GetFileSizeInBytes; }) c.GetFileSizeInBytes = fileSizeInBytes;
  c.user_data = &folder;
  return c;
}

// What the image callback works with. tinygltf calls it while it parses,
// with the model's buffers and bufferViews already read.
struct ImageLoading {
  const tinygltf::Model* model = nullptr;
  MemoryBudget* budget = nullptr;
  // Per glTF image that passed its checks: its encoded bytes, decoded only
  // once the whole scene (every image and mesh) has been priced.
  std::map<int, std::string> encoded;
  std::optional<Error> failure;  // what refuses the file; rethrown once tinygltf returns
};

// tinygltf hands an image stored in a bufferView over as
// &buffer.data[view.byteOffset] and view.byteLength, unchecked; the
// document checks (gltf_document_checks.h) refused a bufferView past its
// buffer before tinygltf ran. Checked again here against the bytes read.
bool imageBytesInBuffer(const tinygltf::Model& model, int bufferView, const unsigned char* bytes, int size) {
  if (bufferView < 0) return true;  // from a URI: tinygltf's own vector
  if (static_cast<std::size_t>(bufferView) >= model.bufferViews.size() || size < 0) return false;
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(bufferView)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) return false;
  const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  return view.byteOffset <= data.size() && view.byteLength <= data.size() - view.byteOffset &&
         static_cast<std::size_t>(size) == view.byteLength && bytes == data.data() + view.byteOffset;
}

// A PNG's width and height from its IHDR chunk, which the format places
// right after the signature. Read here rather than by stbi_info_from_memory:
// stb_image 2.30 (Debian 13) scans on past IHDR to the image data before it
// answers, 2.27 (Debian 12) stops at IHDR, so a file cut after its header
// would be priced on one release and not on the other.
bool pngSize(const unsigned char* bytes, int size, long long& width, long long& height) {
  if (size < 8 + 8 + 13) return false;
  const auto be32 = [&](int at) {
    return std::uint32_t{bytes[at]} << 24 | std::uint32_t{bytes[at + 1]} << 16 | std::uint32_t{bytes[at + 2]} << 8 | std::uint32_t{bytes[at + 3]};
  };
  if (be32(8) != 13 || std::memcmp(bytes + 12, "IHDR", 4) != 0) return false;
  width = be32(16);
  height = be32(20);
  return true;
}

// Accepts PNG and JPEG only, after checking magic bytes and dimensions
// (a PNG's IHDR, a JPEG's frame header by stbi_info_from_memory) so that
// stb_image never sees an absurd header, and prices the decoded pixels
// against the scene budget from that header.
// It keeps the encoded bytes; decodeImage decodes them later.
// An image that cannot be read is left empty with a warning: the model is
// still drawn, untextured.
bool loadImage(tinygltf::Image* image, const int index, std::string* err, std::string* warn, int, int,
               const unsigned char* bytes, int size, void* user) {
  auto& loading = *static_cast<ImageLoading*>(user);
  const std::string name = at("images", static_cast<std::size_t>(index));
  image->image.clear();
  image->width = image->height = 0;
  if (!imageBytesInBuffer(*loading.model, image->bufferView, bytes, size)) {
    loading.failure = Error(name + ": bufferView " + std::to_string(image->bufferView) + " lies outside its buffer (BUFFER_VIEW_TOO_LONG)");
    if (err) *err += loading.failure->what();
    return false;
  }
  const auto skip = [&](const std::string& why) {
    if (warn) *warn += name + ": " + why + "; drawn without this texture\n";
    return true;
  };
  static constexpr unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  static constexpr unsigned char kJpeg[3] = {0xFF, 0xD8, 0xFF};
  const bool png = size >= 8 && std::memcmp(bytes, kPng, 8) == 0;
  const bool jpeg = size >= 3 && std::memcmp(bytes, kJpeg, 3) == 0;
  if (!png && !jpeg) return skip("not a PNG or JPEG image");
  long long width = 0, height = 0;
  if (png) {
    if (!pngSize(bytes, size, width, height)) return skip("unreadable image header");
  } else {
    int jw = 0, jh = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, size, &jw, &jh, &channels)) return skip("unreadable image header");
    width = jw;
    height = jh;
  }
  if (width <= 0 || height <= 0 || width > kMaxTextureSide || height > kMaxTextureSide)
    return skip("image size " + std::to_string(width) + "x" + std::to_string(height) + " is out of range");
  const int w = static_cast<int>(width), h = static_cast<int>(height);
  try {  // from the header, before anything is decoded
    loading.budget->charge(mipChainPixels(w, h) * 4, name + ": " + std::to_string(w) + "x" + std::to_string(h) + " RGBA pixels and their mipmaps");
  } catch (const Error& e) {
    loading.failure = e;
    if (err) *err += e.what();
    return false;
  }
  image->width = w;
  image->height = h;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  loading.encoded[index].assign(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(size));
  return true;
}

// The pixels of an image loadImage kept, bottom row first as facet::Image
// keeps them (glTF images are stored top row first); empty, with a warning,
// when the data after its header does not decode.
Image decodeImage(const std::string& encoded, int index, Warnings& warnings) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(encoded.data()), static_cast<int>(encoded.size()), &w, &h, &channels, 4);
  if (!pixels) {
    warnings.push_back(at("images", static_cast<std::size_t>(index)) + ": cannot decode image (" + stbi_failure_reason() +
                       "); drawn without this texture");
    return {};
  }
  Image out(w, h);
  const std::size_t stride = static_cast<std::size_t>(w) * 4;
  for (int y = 0; y < h; ++y) std::memcpy(&out.at(0, h - 1 - y), pixels + static_cast<std::size_t>(y) * stride, stride);
  stbi_image_free(pixels);
  return out;
}

// [SECTION] Materials and textures

glm::vec3 vec3Of(const std::vector<double>& v, glm::vec3 fallback) {
  if (v.size() < 3) return fallback;
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

float clamp01(double v, float fallback) { return std::isfinite(v) ? std::clamp(static_cast<float>(v), 0.0f, 1.0f) : fallback; }

// A sampler's codes, checked by checkGltfDocument (an absent key keeps facet's choice).
Sampler samplerOf(const tinygltf::Sampler& in) {
  Sampler out;
  if (const auto k = enumIndex(kMagFilterCodes, in.magFilter)) out.mag = static_cast<MagFilter>(*k);
  if (const auto k = enumIndex(kMinFilterCodes, in.minFilter)) out.min = static_cast<MinFilter>(*k);
  if (const auto k = enumIndex(kWrapCodes, in.wrapS)) out.wrapS = static_cast<Wrap>(*k);
  if (const auto k = enumIndex(kWrapCodes, in.wrapT)) out.wrapT = static_cast<Wrap>(*k);
  return out;
}

// Each texture gets its image's pixels, decoded once: the last texture to
// use an image takes them over, any other gets a copy, priced against the budget.
void convertTextures(const tinygltf::Model& model, const std::map<int, std::string>& encoded, MemoryBudget& budget, Scene& scene,
                     Warnings& warnings) {
  std::map<int, std::size_t> lastUse;  // image -> the last texture naming it
  for (std::size_t t = 0; t < model.textures.size(); ++t) lastUse[model.textures[t].source] = t;
  for (std::size_t t = 0; t < model.textures.size(); ++t) {
    const int source = model.textures[t].source;
    if (source >= 0 && static_cast<std::size_t>(source) < model.images.size() && lastUse[source] != t && encoded.count(source)) {
      const tinygltf::Image& image = model.images[static_cast<std::size_t>(source)];
      budget.charge(mipChainPixels(image.width, image.height) * 4,
                    at("textures", t) + ": another copy of the " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                        " pixels of " + at("images", static_cast<std::size_t>(source)));
    }
  }
  // Data textures (metallic-roughness, occlusion) are read as bytes / 255, colour ones as sRGB.
  std::set<int> colour, data;
  for (const tinygltf::Material& material : model.materials) {
    colour.insert({material.pbrMetallicRoughness.baseColorTexture.index, material.emissiveTexture.index});
    data.insert({material.pbrMetallicRoughness.metallicRoughnessTexture.index, material.occlusionTexture.index, material.normalTexture.index});
  }
  std::map<int, Image> decoded;  // images a later texture still needs
  for (std::size_t t = 0; t < model.textures.size(); ++t) {
    Texture texture;
    const int index = static_cast<int>(t);
    if (data.count(index)) {
      if (colour.count(index))
        warnings.push_back(at("textures", t) + ": used both as a colour (sRGB) and as data (linear); read as colour everywhere");
      else
        texture.encoding = TexelEncoding::Linear;
    }
    texture.name = model.textures[t].name;
    const int source = model.textures[t].source;
    if (source < 0 || static_cast<std::size_t>(source) >= model.images.size()) {
      warnings.push_back(at("textures", t) + ": source " + std::to_string(source) + " does not exist (UNRESOLVED_REFERENCE); ignored");
    } else if (const auto bytes = encoded.find(source); bytes != encoded.end()) {
      auto image = decoded.find(source);
      if (image == decoded.end()) image = decoded.emplace(source, decodeImage(bytes->second, source, warnings)).first;
      if (lastUse[source] == t) {
        texture.image = std::move(image->second);
        decoded.erase(image);
      } else {
        texture.image = image->second;
      }
    }
    texture.mips = mipLevels(texture.image, texture.encoding);
    if (const int s = model.textures[t].sampler; s >= 0 && static_cast<std::size_t>(s) < model.samplers.size())
      texture.sampler = samplerOf(model.samplers[static_cast<std::size_t>(s)]);
    scene.textures.push_back(std::move(texture));
  }
}

// KHR_texture_transform on a texture reference: offset, rotation and scale,
// each a finite number (another value is refused, naming the reference).
TextureTransform textureTransformOf(const tinygltf::ExtensionMap& extensions, const std::string& owner) {
  TextureTransform out;
  const auto found = extensions.find("KHR_texture_transform");
  if (found == extensions.end() || !found->second.IsObject()) return out;
  const tinygltf::Value& t = found->second;
  const std::string name = owner + ".extensions.KHR_texture_transform";
  const auto number = [&](const tinygltf::Value& v, const std::string& key) {
    if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble())) throw Error(name + ": " + key + " is not a finite number");
    return static_cast<float>(v.GetNumberAsDouble());
  };
  const auto pair = [&](const char* key, glm::vec2 fallback) {
    if (!t.Has(key)) return fallback;
    const tinygltf::Value& v = t.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 2) throw Error(name + ": " + key + " is not an array of two numbers");
    return glm::vec2(number(v.Get(0), std::string(key) + "[0]"), number(v.Get(1), std::string(key) + "[1]"));
  };
  out.offset = pair("offset", out.offset);
  out.scale = pair("scale", out.scale);
  if (t.Has("rotation")) out.rotation = number(t.Get("rotation"), "rotation");
  return out;
}

// What the ray tracer refracts (PIPELINE.md, "Ray tracing"): KHR_materials_transmission's
// transmissionFactor, KHR_materials_ior's ior, KHR_materials_volume's attenuation.
// A value outside its extension's range is ignored with a warning; the
// textures these extensions allow are not read (a warning says so).
void readRefraction(const tinygltf::Material& src, const std::string& where, Material& material, Warnings& warnings) {
  // A number property of an extension object, or nothing when absent; a value of another type is refused.
  const auto property = [&](const tinygltf::Value& extension, const char* extensionName, const char* key) -> std::optional<double> {
    if (!extension.Has(key)) return std::nullopt;
    const tinygltf::Value& v = extension.Get(key);
    if (!v.IsNumber()) throw Error(where + ": " + extensionName + "." + key + " is not a number");
    return v.GetNumberAsDouble();
  };
  const auto texture = [&](const tinygltf::Value& extension, const char* extensionName, const char* key) {
    if (extension.Has(key)) warnings.push_back(where + ": " + extensionName + "." + key + " is not read; the factor alone applies");
  };
  if (const auto found = src.extensions.find("KHR_materials_transmission"); found != src.extensions.end()) {
    const tinygltf::Value& e = found->second;
    if (const auto t = property(e, "KHR_materials_transmission", "transmissionFactor")) {
      if (*t >= 0 && *t <= 1) material.transmission = static_cast<float>(*t);
      else warnings.push_back(where + ": KHR_materials_transmission.transmissionFactor " + std::to_string(*t) + " is not in [0, 1]; ignored");
    }
    texture(e, "KHR_materials_transmission", "transmissionTexture");
  }
  if (const auto found = src.extensions.find("KHR_materials_ior"); found != src.extensions.end()) {
    if (const auto n = property(found->second, "KHR_materials_ior", "ior")) {
      // 0 is the extension's specular-glossiness compatibility mode: an infinite index, whose Fresnel term is 1 at every angle.
      if (*n == 0) material.ior = std::numeric_limits<float>::infinity();
      else if (std::isfinite(*n) && *n >= 1) material.ior = static_cast<float>(*n);
      else warnings.push_back(where + ": KHR_materials_ior.ior " + std::to_string(*n) + " is neither 0 nor 1 or more; ignored");
    }
  }
  if (const auto found = src.extensions.find("KHR_materials_volume"); found != src.extensions.end()) {
    const tinygltf::Value& e = found->second;
    if (const auto d = property(e, "KHR_materials_volume", "attenuationDistance")) {
      if (std::isfinite(*d) && *d > 0) material.attenuationDistance = static_cast<float>(*d);
      else warnings.push_back(where + ": KHR_materials_volume.attenuationDistance " + std::to_string(*d) + " is not above 0; ignored");
    }
    if (e.Has("attenuationColor")) {
      const tinygltf::Value& c = e.Get("attenuationColor");
      if (!c.IsArray() || c.ArrayLen() != 3) throw Error(where + ": KHR_materials_volume.attenuationColor is not an array of three numbers");
      for (int k = 0; k < 3; ++k) {
        const tinygltf::Value& v = c.Get(k);
        if (!v.IsNumber()) throw Error(where + ": KHR_materials_volume.attenuationColor[" + std::to_string(k) + "] is not a number");
        material.attenuationColor[k] = clamp01(v.GetNumberAsDouble(), 1.0f);
      }
    }
    texture(e, "KHR_materials_volume", "thicknessTexture");
  }
}

void convertMaterials(const tinygltf::Model& model, Scene& scene, Warnings& warnings) {
  for (std::size_t m = 0; m < model.materials.size(); ++m) {
    const tinygltf::Material& src = model.materials[m];
    Material material;
    material.name = src.name;
    const auto& pbr = src.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4)
      material.baseColor = {clamp01(pbr.baseColorFactor[0], 1), clamp01(pbr.baseColorFactor[1], 1),
                            clamp01(pbr.baseColorFactor[2], 1), clamp01(pbr.baseColorFactor[3], 1)};
    material.metallic = clamp01(pbr.metallicFactor, 1.0f);
    material.roughness = clamp01(pbr.roughnessFactor, 1.0f);
    material.emissive = glm::clamp(vec3Of(src.emissiveFactor, glm::vec3(0.0f)), 0.0f, 1.0f);
    if (!std::isfinite(material.emissive.x + material.emissive.y + material.emissive.z)) material.emissive = glm::vec3(0.0f);
    const auto strength = src.extensions.find("KHR_materials_emissive_strength");
    if (strength != src.extensions.end() && strength->second.Has("emissiveStrength")) {
      const double s = strength->second.Get("emissiveStrength").GetNumberAsDouble();
      if (std::isfinite(s) && s >= 0) material.emissive *= static_cast<float>(s);
    }
    readRefraction(src, at("materials", m), material, warnings);
    material.unlit = src.extensions.count("KHR_materials_unlit") > 0;  // the colour is O_d, no illumination
    material.doubleSided = src.doubleSided;
    // alphaMode and alphaCutoff are checked by checkGltfDocument.
    if (src.alphaMode == "MASK") {
      material.alphaMode = AlphaMode::Mask;
      material.alphaCutoff = static_cast<float>(src.alphaCutoff);
    } else if (src.alphaMode == "BLEND") {
      material.alphaMode = AlphaMode::Blend;
    }
    material.baseColorTransform = textureTransformOf(pbr.baseColorTexture.extensions, at("materials", m) + ": baseColorTexture");
    // A texture reference: its index when it names a texture with an image, else -1 with a warning;
    // `set` gets the TEXCOORD_n it reads (0 or 1).
    const auto reference = [&](const char* key, int texture, int texCoord, const tinygltf::ExtensionMap& extensions, bool transformed, int& set) {
      if (texture < 0) return -1;
      if (static_cast<std::size_t>(texture) >= scene.textures.size()) {
        warnings.push_back(at("materials", m) + ": " + key + " " + std::to_string(texture) + " does not exist (UNRESOLVED_REFERENCE); ignored");
        return -1;
      }
      if (scene.textures[static_cast<std::size_t>(texture)].image.empty()) {
        warnings.push_back(at("materials", m) + ": " + key + " " + std::to_string(texture) + " has no image; ignored");
        return -1;
      }
      set = texCoord == 1 ? 1 : 0;
      if (texCoord < 0 || texCoord > 1)
        warnings.push_back(at("materials", m) + ": " + key + " uses TEXCOORD_" + std::to_string(texCoord) +
                           "; facet reads TEXCOORD_0 and TEXCOORD_1, and TEXCOORD_0 is used instead");
      if (!transformed && extensions.count("KHR_texture_transform"))
        warnings.push_back(at("materials", m) + ": " + key + "'s KHR_texture_transform is ignored (only the base colour texture's is applied)");
      return texture;
    };
    TexcoordSets& sets = material.texcoordSets;
    const auto& base = pbr.baseColorTexture;
    material.baseColorTexture = reference("baseColorTexture", base.index, base.texCoord, base.extensions, true, sets.baseColor);
    const auto& mr = pbr.metallicRoughnessTexture;
    material.metallicRoughnessTexture = reference("metallicRoughnessTexture", mr.index, mr.texCoord, mr.extensions, false, sets.metallicRoughness);
    const auto& occlusion = src.occlusionTexture;
    material.occlusionTexture = reference("occlusionTexture", occlusion.index, occlusion.texCoord, occlusion.extensions, false, sets.occlusion);
    material.occlusionStrength = clamp01(occlusion.strength, 1.0f);
    const auto& normal = src.normalTexture;
    material.normalTexture = reference("normalTexture", normal.index, normal.texCoord, normal.extensions, false, sets.normal);
    material.normalScale = std::isfinite(normal.scale) ? static_cast<float>(normal.scale) : 1.0f;
    const auto& emissive = src.emissiveTexture;
    material.emissiveTexture = reference("emissiveTexture", emissive.index, emissive.texCoord, emissive.extensions, false, sets.emissive);
    scene.materials.push_back(material);
  }
}

// [SECTION] Primitives to meshes

// A primitive's index list turned into a triangle list in place (mode 4
// list, 5 strip, 6 fan): a list keeps its whole triangles, a strip or a fan
// becomes three indices per triangle.
void toTriangleList(std::vector<std::uint32_t>& idx, int mode) {
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    idx.resize(idx.size() / 3 * 3);
    return;
  }
  std::vector<std::uint32_t> out;
  out.reserve(idx.size() > 2 ? 3 * (idx.size() - 2) : 0);
  if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 2; i < idx.size(); ++i) {  // every other triangle flips to keep the strip's winding
      if (i % 2 == 0) out.insert(out.end(), {idx[i - 2], idx[i - 1], idx[i]});
      else out.insert(out.end(), {idx[i - 1], idx[i - 2], idx[i]});
    }
  } else {  // fan
    for (std::size_t i = 2; i < idx.size(); ++i) out.insert(out.end(), {idx[0], idx[i - 1], idx[i]});
  }
  idx = std::move(out);
}

// The same for lines (mode 1 list, 2 loop, 3 strip): two indices per segment,
// a loop closed from its last vertex back to its first.
void toSegmentList(std::vector<std::uint32_t>& idx, int mode) {
  if (mode == TINYGLTF_MODE_LINE) {
    idx.resize(idx.size() / 2 * 2);
    return;
  }
  std::vector<std::uint32_t> out;
  out.reserve(2 * idx.size());
  for (std::size_t i = 1; i < idx.size(); ++i) out.insert(out.end(), {idx[i - 1], idx[i]});
  if (mode == TINYGLTF_MODE_LINE_LOOP && idx.size() > 2) out.insert(out.end(), {idx.back(), idx.front()});
  idx = std::move(out);
}

// Indices per primitive of a glTF mode: 1 for POINTS, 2 for the line modes, 3 for the triangle modes, 0 for no mode.
int indicesPerPrimitive(int mode) {
  if (mode == TINYGLTF_MODE_POINTS) return 1;
  if (mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) return 2;
  if (mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN) return 3;
  return 0;
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// "1e+18": the limit as messages show it.
std::string coordinateLimit() {
  char text[32];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(kMaxWorldCoordinate));
  return text;
}

// Finite and inside ±kMaxWorldCoordinate (settings/render_settings.h).
bool drawable(glm::vec3 v) {
  return std::fabs(v.x) <= kMaxWorldCoordinate && std::fabs(v.y) <= kMaxWorldCoordinate && std::fabs(v.z) <= kMaxWorldCoordinate;
}

// The TEXCOORD_n attribute name of set 0 or 1.
const char* texcoordAttribute(int set) { return set == 1 ? "TEXCOORD_1" : "TEXCOORD_0"; }

// The set a primitive's normal texture reads (as loadMaterials resolves texCoord), or -1 when its material has none.
int normalTextureSet(const tinygltf::Model& model, const tinygltf::Primitive& prim) {
  if (prim.material < 0 || static_cast<std::size_t>(prim.material) >= model.materials.size()) return -1;
  const tinygltf::NormalTextureInfo& normal = model.materials[static_cast<std::size_t>(prim.material)].normalTexture;
  return normal.index < 0 ? -1 : normal.texCoord == 1 ? 1 : 0;
}

// Whether a primitive's mesh gets tangents: its material has a normal texture and it has that texture's set.
bool needsTangents(const tinygltf::Model& model, const tinygltf::Primitive& prim) {
  const int set = normalTextureSet(model, prim);
  return set >= 0 && prim.attributes.count(texcoordAttribute(set));
}

// What a primitive's mesh will hold, priced from its accessors' counts
// before any is read: positions and normals (read or computed), texture
// coordinates, and its indices (a strip or fan's triangle list besides).
void pricePrimitive(const tinygltf::Model& model, const tinygltf::Primitive& prim, int mode, int positionAccessor, const std::string& name,
                    MemoryBudget& budget) {
  const std::uint64_t vertices = accessorCount(model, positionAccessor);
  const std::uint64_t indices = prim.indices >= 0 ? accessorCount(model, prim.indices) : vertices;
  std::uint64_t bytes = vertices * (sizeof(glm::vec3) + sizeof(glm::vec3)) + indices * sizeof(std::uint32_t);
  for (int set = 0; set < 2; ++set)
    if (prim.attributes.count(texcoordAttribute(set))) bytes += vertices * sizeof(glm::vec2);
  if (prim.attributes.count("COLOR_0")) bytes += vertices * sizeof(glm::vec4);
  if (needsTangents(model, prim)) bytes += vertices * sizeof(glm::vec4);
  const bool strip = mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN;
  if (strip && indices > 2) bytes += 3 * (indices - 2) * sizeof(std::uint32_t);
  if (mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) bytes += 2 * indices * sizeof(std::uint32_t);
  budget.charge(bytes, name + ": " + std::to_string(vertices) + " vertices (" + at("accessors", static_cast<std::size_t>(positionAccessor)) +
                           ") and " + std::to_string(indices) + " indices");
}

// Converts one primitive; returns false (with a warning) when it is skipped.
// Throws facet::Error when it does not fit the scene budget.
bool convertPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& name, MemoryBudget& budget, Mesh& mesh,
                      Warnings& warnings) {
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  const int corners = indicesPerPrimitive(mode);  // 1 point, 2 segment, 3 triangle
  if (corners == 0) {
    warnings.push_back(name + ": mode " + std::to_string(mode) + " is not a glTF primitive mode (0 to 6); skipped");
    return false;
  }
  const char* primitive = corners == 3 ? "triangle" : corners == 2 ? "segment" : "point";
  const auto position = prim.attributes.find("POSITION");
  if (position == prim.attributes.end()) {
    warnings.push_back(name + ": no POSITION attribute; skipped");
    return false;
  }
  pricePrimitive(model, prim, mode, position->second, name, budget);
  const std::string positions = "POSITION " + at("accessors", static_cast<std::size_t>(std::max(position->second, 0)));
  try {
    mesh.positions = readPositions(model, position->second);
    std::vector<std::uint32_t> triangles;
    if (prim.indices >= 0) {
      triangles = readIndices(model, prim.indices);
    } else {
      triangles.resize(mesh.positions.size());
      for (std::size_t i = 0; i < triangles.size(); ++i) triangles[i] = static_cast<std::uint32_t>(i);
    }
    if ((mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_LINE) && triangles.size() % static_cast<std::size_t>(corners) != 0)
      warnings.push_back(name + ": " + std::to_string(triangles.size()) + " indices is not a multiple of " + std::to_string(corners) + "; the last " +
                         std::to_string(triangles.size() % static_cast<std::size_t>(corners)) + " ignored");
    if (corners == 3) toTriangleList(triangles, mode);
    if (corners == 2) toSegmentList(triangles, mode);

    // Keep the primitives (triangles, segments, points) whose indices are in
    // range and whose vertices are finite and inside the coordinates facet
    // draws (compacted in place).
    const auto vertexCount = mesh.positions.size();
    std::vector<char> usable(vertexCount);
    std::size_t notFinite = 0, tooFar = 0;
    for (std::size_t v = 0; v < vertexCount; ++v) {
      const glm::vec3 p = mesh.positions[v];
      usable[v] = finite(p) && drawable(p);
      if (!finite(p)) ++notFinite;
      else if (!drawable(p)) ++tooFar;
    }
    std::size_t outOfRange = 0, kept = 0;
    const auto per = static_cast<std::size_t>(corners);
    for (std::size_t t = 0; t + per <= triangles.size(); t += per) {
      bool inRange = true, drawn = true;
      for (std::size_t j = 0; j < per; ++j) {
        inRange = inRange && triangles[t + j] < vertexCount;
        drawn = drawn && inRange && usable[triangles[t + j]];  // an unusable vertex is counted once, above
      }
      if (!inRange) ++outOfRange;
      if (!drawn) continue;
      for (std::size_t j = 0; j < per; ++j) triangles[kept++] = triangles[t + j];
    }
    triangles.resize(kept);
    std::vector<std::uint32_t>& drawnIndices = corners == 3 ? mesh.indices : corners == 2 ? mesh.lines : mesh.points;
    drawnIndices = std::move(triangles);
    if (outOfRange)
      warnings.push_back(name + ": " + countOf(outOfRange, primitive) + " with an index past the " + countOf(vertexCount, "vertex", "vertices") +
                         " (ACCESSOR_INDEX_OOB); dropped");
    if (notFinite)
      warnings.push_back(name + ": " + positions + " has " + countOf(notFinite, "NaN or infinite position") +
                         " (ACCESSOR_INVALID_FLOAT); their " + primitive + "s dropped");
    if (tooFar)
      warnings.push_back(name + ": " + positions + " has " + countOf(tooFar, "position") + " beyond +-" + coordinateLimit() +
                         ", farther than facet draws; their " + primitive + "s dropped");
    if (drawnIndices.empty()) {
      warnings.push_back(name + ": no drawable " + primitive + "s; skipped");
      return false;
    }
    // The vertices no kept primitive uses move onto one that is, so that the
    // bounds (and the framing) see only what is drawn.
    if (notFinite || tooFar)
      for (std::size_t v = 0; v < vertexCount; ++v)
        if (!usable[v]) mesh.positions[v] = mesh.positions[drawnIndices[0]];

    bool normalsOk = false;
    if (const auto normal = prim.attributes.find("NORMAL"); normal != prim.attributes.end()) {
      try {
        mesh.normals = readNormals(model, normal->second);
        if (mesh.normals.size() != vertexCount) {
          warnings.push_back(name + ": NORMAL has " + std::to_string(mesh.normals.size()) + " elements for " + std::to_string(vertexCount) +
                             " positions (MESH_PRIMITIVE_UNEQUAL_ACCESSOR_COUNT); normals recomputed");
        } else {
          std::size_t bad = 0;
          for (glm::vec3& n : mesh.normals) {
            const float length = glm::length(n);
            if (!std::isfinite(length) || length < 1e-6f) ++bad;
            else n /= length;
          }
          if (bad) warnings.push_back(name + ": " + countOf(bad, "normal") + " zero, NaN or infinite; normals recomputed");
          normalsOk = bad == 0;
        }
      } catch (const AccessorError& e) {
        warnings.push_back(name + ": NORMAL " + e.message + "; normals recomputed");
      }
    }
    if (!normalsOk) computeVertexNormals(mesh);  // points and lines, which are unlit, get (0, 0, 1)

    for (int set = 0; set < 2; ++set) {
      const char* key = texcoordAttribute(set);
      const auto uv = prim.attributes.find(key);
      if (uv == prim.attributes.end()) continue;
      std::vector<glm::vec2>& texcoords = set == 1 ? mesh.texcoords1 : mesh.texcoords;
      try {
        texcoords = readVec2(model, uv->second);
        if (texcoords.size() != vertexCount) {
          warnings.push_back(name + ": " + key + " count differs from POSITION (MESH_PRIMITIVE_UNEQUAL_ACCESSOR_COUNT); ignored");
          texcoords.clear();
        }
      } catch (const AccessorError& e) {
        warnings.push_back(name + ": " + key + " " + e.message + "; ignored");
        texcoords.clear();
      }
    }

    if (const auto color = prim.attributes.find("COLOR_0"); color != prim.attributes.end()) {
      try {
        mesh.colors = readColors(model, color->second);
        if (mesh.colors.size() != vertexCount) {
          warnings.push_back(name + ": COLOR_0 count differs from POSITION (MESH_PRIMITIVE_UNEQUAL_ACCESSOR_COUNT); ignored");
          mesh.colors.clear();
        }
        // glTF holds colours to [0, 1]; one outside (or NaN, taken as 1) is clamped.
        std::size_t outside = 0;
        for (glm::vec4& c : mesh.colors)
          for (int k = 0; k < 4; ++k)
            if (!(c[k] >= 0.0f && c[k] <= 1.0f)) {
              ++outside;
              c[k] = c[k] < 0.0f ? 0.0f : 1.0f;
            }
        if (outside) warnings.push_back(name + ": COLOR_0 has " + countOf(outside, "component") + " outside [0, 1] (ACCESSOR_INVALID_FLOAT); clamped");
      } catch (const AccessorError& e) {
        warnings.push_back(name + ": COLOR_0 " + e.message + "; ignored");
        mesh.colors.clear();
      }
    }
    // Tangents for a normal texture: the file's TANGENT (unit xyz, w ±1) where it is sound, else computed.
    if (corners == 3 && needsTangents(model, prim) && !mesh.texcoordSet(normalTextureSet(model, prim)).empty()) {
      if (const auto tangent = prim.attributes.find("TANGENT"); tangent != prim.attributes.end()) {
        try {
          mesh.tangents = readTangents(model, tangent->second);
          std::size_t bad = 0;
          for (const glm::vec4& t : mesh.tangents)
            if (!std::isfinite(t.x + t.y + t.z) || !(std::fabs(glm::length(glm::vec3(t)) - 1.0f) < 1e-2f) || !(t.w == 1.0f || t.w == -1.0f)) ++bad;
          if (mesh.tangents.size() != vertexCount || bad) {
            warnings.push_back(name + ": TANGENT has " + (bad ? countOf(bad, "element") + " not unit with w = +-1" : std::string("another count than POSITION")) +
                               "; tangents computed");
            mesh.tangents.clear();
          }
        } catch (const AccessorError& e) {
          warnings.push_back(name + ": TANGENT " + e.message + "; tangents computed");
          mesh.tangents.clear();
        }
      }
      if (mesh.tangents.empty()) computeVertexTangents(mesh, normalTextureSet(model, prim));
    }
  } catch (const AccessorError& e) {
    warnings.push_back(name + ": " + e.message + "; skipped");
    return false;
  }
  if (prim.material >= 0 && static_cast<std::size_t>(prim.material) >= model.materials.size()) {
    warnings.push_back(name + ": material " + std::to_string(prim.material) + " does not exist (UNRESOLVED_REFERENCE); default material used");
  } else {
    mesh.material = prim.material;
  }
  if (!prim.targets.empty()) warnings.push_back(name + ": morph targets are not supported; base shape drawn");
  return true;
}

// One warning per texture a mesh's material has and the mesh cannot read: it
// lacks the texture coordinate set the reference names (PIPELINE.md,
// "Textures": the factor alone). Lines and points read no texture.
void warnUnreadTextures(const Scene& scene, const std::vector<std::vector<int>>& meshTable, Warnings& warnings) {
  for (std::size_t m = 0; m < meshTable.size(); ++m)
    for (std::size_t p = 0; p < meshTable[m].size(); ++p) {
      if (meshTable[m][p] < 0) continue;
      const Mesh& mesh = scene.meshes[static_cast<std::size_t>(meshTable[m][p])];
      if (mesh.indices.empty() || mesh.material < 0 || static_cast<std::size_t>(mesh.material) >= scene.materials.size()) continue;
      const Material& material = scene.materials[static_cast<std::size_t>(mesh.material)];
      const TexcoordSets& sets = material.texcoordSets;
      const struct {
        const char* key;
        int texture, set;
      } references[] = {{"baseColorTexture", material.baseColorTexture, sets.baseColor},
                        {"metallicRoughnessTexture", material.metallicRoughnessTexture, sets.metallicRoughness},
                        {"occlusionTexture", material.occlusionTexture, sets.occlusion},
                        {"emissiveTexture", material.emissiveTexture, sets.emissive},
                        {"normalTexture", material.normalTexture, sets.normal}};
      for (const auto& r : references)
        if (r.texture >= 0 && mesh.texcoordSet(r.set).empty())
          warnings.push_back(at("meshes", m) + "." + at("primitives", p) + ": " + at("materials", static_cast<std::size_t>(mesh.material)) + "'s " +
                             r.key + " reads " + texcoordAttribute(r.set) + ", which the primitive does not have; not read");
    }
}

// scene mesh index per glTF mesh and primitive (-1: skipped)
std::vector<std::vector<int>> convertMeshes(const tinygltf::Model& model, MemoryBudget& budget, Scene& scene, Warnings& warnings) {
  std::vector<std::vector<int>> table(model.meshes.size());
  for (std::size_t m = 0; m < model.meshes.size(); ++m) {
    const tinygltf::Mesh& src = model.meshes[m];
    for (std::size_t p = 0; p < src.primitives.size(); ++p) {
      const std::string name = at("meshes", m) + "." + at("primitives", p);
      Mesh mesh;
      mesh.name = src.name.empty() ? name : src.name;
      if (convertPrimitive(model, src.primitives[p], name, budget, mesh, warnings)) {
        scene.meshes.push_back(std::move(mesh));
        table[m].push_back(static_cast<int>(scene.meshes.size() - 1));
      } else {
        table[m].push_back(-1);
      }
    }
  }
  return table;
}

// [SECTION] Nodes: world transforms, instances, cameras, lights

bool finiteMatrix(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

// The node's local matrix: its `matrix`, or T·R·S (glTF, course order).
glm::mat4 localMatrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(node.matrix[static_cast<std::size_t>(i)]);  // column-major, as glTF
    return m;
  }
  const glm::vec3 t = vec3Of(node.translation, glm::vec3(0.0f));
  const glm::vec3 s = vec3Of(node.scale, glm::vec3(1.0f));
  glm::mat4 r(1.0f);
  if (node.rotation.size() == 4) {
    const glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                      static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
    const float length = glm::length(q);
    if (length > 0.0f && std::isfinite(length)) r = glm::mat4_cast(q / length);
  }
  return translation(t) * r * scaling(s);
}

// The world-space box of a mesh placed by `world`: the box of the eight
// corners of its model-space box.
Bounds placedBounds(const Bounds& model, const glm::mat4& world) {
  Bounds placed;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p(corner & 1 ? model.max.x : model.min.x, corner & 2 ? model.max.y : model.min.y, corner & 4 ? model.max.z : model.min.z);
    placed.include(glm::vec3(world * glm::vec4(p, 1.0f)));
  }
  return placed;
}

// glTF's node animations (3.11) of the nodes the walk placed: translation,
// rotation and scale channels with float keys, LINEAR, STEP or CUBICSPLINE.
// A channel that cannot be read (an accessor out of its buffer, times not
// increasing or not finite, counts that do not match, normalized integer
// rotations, morph weights) is skipped with a warning naming it; the rest
// of the file loads.
void readAnimations(const tinygltf::Model& model, const std::vector<int>& animatedIndex, MemoryBudget& budget, SceneAnimation& animation,
                    Warnings& warnings) {
  for (std::size_t a = 0; a < model.animations.size(); ++a) {
    const tinygltf::Animation& source = model.animations[a];
    for (std::size_t c = 0; c < source.channels.size(); ++c) {
      const tinygltf::AnimationChannel& channel = source.channels[c];
      const std::string where = at("animations", a) + ".channels[" + std::to_string(c) + "]";
      const auto skip = [&](const std::string& why) { warnings.push_back(where + ": " + why + "; not animated"); };
      AnimationChannel out;
      if (channel.target_path == "translation") out.path = AnimatedPath::Translation;
      else if (channel.target_path == "rotation") out.path = AnimatedPath::Rotation;
      else if (channel.target_path == "scale") out.path = AnimatedPath::Scale;
      else {
        skip("target path " + quoteInput(channel.target_path) + " (morph weights) moves nothing facet draws");
        continue;
      }
      if (channel.target_node < 0 || static_cast<std::size_t>(channel.target_node) >= animatedIndex.size() ||
          animatedIndex[static_cast<std::size_t>(channel.target_node)] < 0)
        continue;  // a node the scene does not place (a skin's joint, another scene's)
      out.node = animatedIndex[static_cast<std::size_t>(channel.target_node)];
      if (channel.sampler < 0 || static_cast<std::size_t>(channel.sampler) >= source.samplers.size()) {
        skip("sampler " + std::to_string(channel.sampler) + " does not exist");
        continue;
      }
      const tinygltf::AnimationSampler& sampler = source.samplers[static_cast<std::size_t>(channel.sampler)];
      if (sampler.interpolation == "STEP") out.interpolation = KeyInterpolation::Step;
      else if (sampler.interpolation == "CUBICSPLINE") out.interpolation = KeyInterpolation::CubicSpline;
      else if (sampler.interpolation.empty() || sampler.interpolation == "LINEAR") out.interpolation = KeyInterpolation::Linear;
      else {
        skip("interpolation " + quoteInput(sampler.interpolation) + " is not LINEAR, STEP or CUBICSPLINE");
        continue;
      }
      // Priced first: a key's time, and a value of 16 bytes per output element.
      const std::uint64_t bytes = accessorCount(model, sampler.input) * sizeof(float) + accessorCount(model, sampler.output) * sizeof(glm::vec4);
      budget.charge(bytes, where + ": " + std::to_string(accessorCount(model, sampler.input)) + " keys");
      try {
        out.times = readScalars(model, sampler.input);
        if (out.path == AnimatedPath::Rotation) out.values = readVec4(model, sampler.output);
        else for (const glm::vec3 v : readVec3(model, sampler.output)) out.values.emplace_back(v, 0.0f);
      } catch (const AccessorError& e) {
        skip(e.message);
        continue;
      }
      const std::size_t perKey = out.interpolation == KeyInterpolation::CubicSpline ? 3 : 1;
      bool increasing = !out.times.empty();
      for (std::size_t k = 0; k < out.times.size(); ++k)
        increasing = increasing && std::isfinite(out.times[k]) && (k == 0 || out.times[k] > out.times[k - 1]);
      const bool finiteValues = std::all_of(out.values.begin(), out.values.end(), [](const glm::vec4& v) { return finite(glm::vec3(v)) && std::isfinite(v.w); });
      if (!increasing) skip("key times are not finite and strictly increasing");
      else if (out.values.size() != perKey * out.times.size())
        skip(std::to_string(out.values.size()) + " values for " + std::to_string(out.times.size()) + " keys (" + std::to_string(perKey) + " a key)");
      else if (!finiteValues) skip("a value is not finite");
      else animation.channels.push_back(std::move(out));
    }
  }
}

// Walks the node trees from the scene's roots. The document checks
// (gltf_document_checks.h) refused a node with two parents and a loop, so
// each node is met at most once and the walk is linear in the file.
// A tinygltf value (a node's extras) as JSON, for the settings reader; nested at most 8 deep.
nlohmann::json jsonOf(const tinygltf::Value& v, int depth) {
  if (depth > 8) throw Error("extras: nested deeper than 8 levels");
  if (v.IsBool()) return v.Get<bool>();
  if (v.IsInt()) return v.Get<int>();
  if (v.IsNumber()) return v.GetNumberAsDouble();
  if (v.IsString()) return v.Get<std::string>();
  if (v.IsArray()) {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i = 0; i < v.ArrayLen(); ++i) out.push_back(jsonOf(v.Get(static_cast<int>(i)), depth + 1));
    return out;
  }
  if (v.IsObject()) {
    nlohmann::json out = nlohmann::json::object();
    for (const std::string& key : v.Keys()) out[key] = jsonOf(v.Get(key), depth + 1);
    return out;
  }
  return nullptr;
}

struct NodeWalker {
  const tinygltf::Model& model;
  Scene& scene;
  Warnings& warnings;
  const std::vector<std::vector<int>>& meshTable;
  std::vector<char> visited;
  std::map<int, Bounds> modelBounds;  // per scene mesh, once
  // What the instances will need of a frame (memory_budget.h), priced as
  // each is placed, so that many nodes naming one big mesh are refused here.
  MemoryBudget frameBudget{kFrameMemoryBudget, "frame budget"};
  // The node tree as the animation needs it (scene/animation.h): each visited
  // file node's index there, -1 for one not visited.
  std::vector<int> animatedIndex = std::vector<int>(model.nodes.size(), -1);

  void visit(int index, const glm::mat4& parent, int depth, int parentNode = -1) {
    const auto n = static_cast<std::size_t>(index);
    if (index < 0 || n >= model.nodes.size()) {
      warnings.push_back("node " + std::to_string(index) + " does not exist (UNRESOLVED_REFERENCE); ignored");
      return;
    }
    if (visited[n]) throw Error(at("nodes", n) + ": is reached twice in the node hierarchy (NODE_PARENT_OVERRIDE)");
    visited[n] = 1;
    if (depth > kMaxGltfNodeDepth) {
      warnings.push_back(at("nodes", n) + ": deeper than " + std::to_string(kMaxGltfNodeDepth) + " levels; its subtree is skipped");
      return;
    }
    const tinygltf::Node& node = model.nodes[n];
    const glm::mat4 local = localMatrix(node);
    const glm::mat4 world = parent * local;
    if (!finiteMatrix(world)) {
      warnings.push_back(at("nodes", n) + ": transform is not finite; its subtree is skipped");
      return;
    }
    AnimatedNode animated;
    animated.parent = parentNode;
    animated.translation = vec3Of(node.translation, glm::vec3(0.0f));
    animated.scale = vec3Of(node.scale, glm::vec3(1.0f));
    if (node.rotation.size() == 4)
      animated.rotation = glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]), static_cast<float>(node.rotation[1]),
                                    static_cast<float>(node.rotation[2]));
    animated.hasMatrix = node.matrix.size() == 16;
    animated.local = local;
    const int self = static_cast<int>(scene.animation.nodes.size());
    scene.animation.nodes.push_back(animated);
    animatedIndex[n] = self;
    if (node.mesh >= 0) {
      if (static_cast<std::size_t>(node.mesh) >= meshTable.size()) {
        warnings.push_back(at("nodes", n) + ": mesh " + std::to_string(node.mesh) + " does not exist (UNRESOLVED_REFERENCE); ignored");
      } else {
        for (int sceneMesh : meshTable[static_cast<std::size_t>(node.mesh)]) {
          if (sceneMesh < 0) continue;
          const Mesh& mesh = scene.meshes[static_cast<std::size_t>(sceneMesh)];
          auto bounds = modelBounds.find(sceneMesh);
          if (bounds == modelBounds.end()) {
            bounds = modelBounds.emplace(sceneMesh, Bounds{}).first;
            for (const glm::vec3& p : mesh.positions) bounds->second.include(p);
          }
          const Bounds placed = placedBounds(bounds->second, world);
          if (!finite(placed.min) || !finite(placed.max) || !drawable(placed.min) || !drawable(placed.max)) {
            warnings.push_back(at("nodes", n) + ": places " + at("meshes", static_cast<std::size_t>(node.mesh)) + " beyond +-" + coordinateLimit() +
                               ", farther than facet draws; that instance is skipped");
            continue;
          }
          const std::uint64_t bytes = instanceFrameBytes(mesh.positions.size(), mesh.triangleCount());
          frameBudget.charge(bytes, frameBudget.fits(bytes) ? std::string()
                                                            : at("nodes", n) + ": the " + std::to_string(mesh.positions.size()) + " vertices and " +
                                                                  std::to_string(mesh.triangleCount()) + " triangles of its instance of " +
                                                                  at("meshes", static_cast<std::size_t>(node.mesh)));
          scene.instances.push_back({sceneMesh, world});
          scene.animation.instanceNodes.push_back(self);
        }
      }
      if (node.skin >= 0) warnings.push_back(at("nodes", n) + ": skinning is not supported; drawn in bind pose");
    }
    if (node.camera >= 0) addCamera(node, n, world);
    addLight(node, n, world);
    addEmitter(node, n, world);
    for (int child : node.children) visit(child, world, depth + 1, self);
  }

  // A particle emitter in the node's extras (renderer/PIPELINE.md, section
  // 12): {"facet_particles": {particles.N's keys}}, its position and
  // direction in the node's frame.
  void addEmitter(const tinygltf::Node& node, std::size_t n, const glm::mat4& world) {
    if (!node.extras.IsObject() || !node.extras.Has("facet_particles")) return;
    Emitter emitter = emitterFromJson(jsonOf(node.extras.Get("facet_particles"), 0), at("nodes", n) + ".extras.facet_particles");
    emitter.position = glm::vec3(world * glm::vec4(emitter.position, 1.0f));
    emitter.direction = glm::vec3(world * glm::vec4(emitter.direction, 0.0f));
    if (!drawable(emitter.position) || !(glm::length(emitter.direction) > 0.0f)) {
      warnings.push_back(at("nodes", n) + ": its particle emitter is placed beyond +-" + coordinateLimit() + " or scaled to nothing; ignored");
      return;
    }
    scene.emitters.push_back(emitter);
  }

  void addCamera(const tinygltf::Node& node, std::size_t n, const glm::mat4& world) {
    if (static_cast<std::size_t>(node.camera) >= model.cameras.size()) {
      warnings.push_back(at("nodes", n) + ": camera " + std::to_string(node.camera) + " does not exist (UNRESOLVED_REFERENCE); ignored");
      return;
    }
    const tinygltf::Camera& src = model.cameras[static_cast<std::size_t>(node.camera)];
    SceneCamera camera;
    camera.name = src.name.empty() ? at("cameras", static_cast<std::size_t>(node.camera)) : src.name;
    // A glTF camera looks down its local -z with +y up.
    camera.eye = glm::vec3(world * glm::vec4(0, 0, 0, 1));
    const glm::vec3 forward = glm::normalize(glm::vec3(world * glm::vec4(0, 0, -1, 0)));
    camera.reference = pointAlong(camera.eye, forward);
    camera.up = glm::normalize(glm::vec3(world * glm::vec4(0, 1, 0, 0)));
    if (src.type == "orthographic") {
      camera.projection = ProjectionKind::Parallel;
      camera.xmag = static_cast<float>(std::fabs(src.orthographic.xmag));
      camera.ymag = static_cast<float>(std::fabs(src.orthographic.ymag));
      camera.near = static_cast<float>(src.orthographic.znear);
      camera.far = static_cast<float>(src.orthographic.zfar);
    } else {
      camera.projection = ProjectionKind::Perspective;
      camera.yfov = static_cast<float>(src.perspective.yfov);
      if (src.perspective.aspectRatio > 0) camera.aspectRatio = static_cast<float>(src.perspective.aspectRatio);
      camera.near = static_cast<float>(src.perspective.znear);
      if (src.perspective.zfar > 0) camera.far = static_cast<float>(src.perspective.zfar);
    }
    const bool sane = finite(camera.eye) && drawable(camera.eye) && finite(forward) && finite(camera.up) && std::isfinite(camera.near) &&
                      (camera.projection == ProjectionKind::Parallel
                           ? camera.xmag > 0 && camera.ymag > 0 && std::isfinite(camera.xmag + camera.ymag) && camera.far && *camera.far > camera.near
                           : camera.yfov > 0 && camera.yfov < 3.1f && camera.near > 0 && (!camera.far || *camera.far > camera.near));
    if (!sane) {
      warnings.push_back(at("cameras", static_cast<std::size_t>(node.camera)) + ": invalid parameters; ignored");
      return;
    }
    scene.cameras.push_back(camera);
  }

  void addLight(const tinygltf::Node& node, std::size_t n, const glm::mat4& world) {
    const auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end() || !ext->second.Has("light")) return;
    // Read as a double: tinygltf's GetNumberAsInt converts 1e75 to int, which is undefined.
    const tinygltf::Value& reference = ext->second.Get("light");
    const double index = reference.IsNumber() ? reference.GetNumberAsDouble() : -1.0;
    if (!(index >= 0.0) || index != std::floor(index) || index >= static_cast<double>(model.lights.size())) {
      warnings.push_back(at("nodes", n) + ": KHR_lights_punctual light " + (reference.IsNumber() ? exactNumber(index) : std::string("(not a number)")) +
                         " does not exist (UNRESOLVED_REFERENCE); ignored");
      return;
    }
    const tinygltf::Light& src = model.lights[static_cast<std::size_t>(index)];
    Light light;
    light.position = glm::vec3(world * glm::vec4(0, 0, 0, 1));
    light.direction = glm::normalize(glm::vec3(world * glm::vec4(0, 0, -1, 0)));  // lights shine down local -z
    light.color = glm::clamp(vec3Of(src.color, glm::vec3(1.0f)), 0.0f, 1.0f);
    light.intensity = static_cast<float>(src.intensity);
    if (src.type == "directional") {
      light.kind = LightKind::Directional;
      light.attenuation = {1, 0, 0};
    } else {
      // glTF point and spot intensities are in candela and fall off with the
      // inverse square of the distance: c1 = c2 = 0, c3 = 1.
      light.kind = src.type == "spot" ? LightKind::Spot : LightKind::Point;
      light.attenuation = {0, 0, 1};
      light.spotCutoffDeg = static_cast<float>(glm::degrees(src.spot.outerConeAngle));
    }
    const bool placed = finite(light.position) && (light.kind == LightKind::Directional || drawable(light.position));
    if (!placed || !finite(light.direction) || !std::isfinite(light.intensity) || light.intensity < 0) {
      warnings.push_back(at("nodes", n) + ": light has a non-finite intensity, or a placement that is not finite or beyond +-" + coordinateLimit() + "; ignored");
      return;
    }
    scene.lights.push_back(light);
  }
};

const std::set<std::string> kSupportedExtensions = {"KHR_lights_punctual",        "KHR_materials_emissive_strength", "KHR_materials_ior",
                                                    "KHR_materials_transmission", "KHR_materials_unlit",             "KHR_materials_volume",
                                                    "KHR_mesh_quantization",      "KHR_texture_transform"};

// glTF's rule: a file whose extensionsRequired names an extension the reader
// lacks is refused. Checked before tinygltf parses, which would otherwise
// fail later on what the extension changes (e.g. Draco's missing bufferViews).
void checkRequiredExtensions(const std::string& path, const nlohmann::json& document) {
  const auto required = document.find("extensionsRequired");
  if (required == document.end() || !required->is_array()) return;
  for (const nlohmann::json& name : *required)
    if (name.is_string() && !kSupportedExtensions.count(name.get<std::string>()))
      throw Error(path + ": requires extension " + quoteInput(name.get<std::string>()) + ", which facet does not support");
}

// tinygltf 2.7 refuses a few valid files. What it requires that glTF 2.0
// does not, and how facet reads such a file:
// - animations[].channels[].target.node: optional ("when undefined, the
//   animated object MAY be defined by an extension", e.g.
//   KHR_animation_pointer). facet animates nodes only; such a channel is taken
//   out of the document before tinygltf parses it, with a warning.
// - skins[].inverseBindMatrices: optional (identity matrices). tinygltf
//   parses the skin and then reports the property missing; that report is
//   dropped (kTolerated below). facet draws no skinning either way.
// - accessors[].bufferView: optional (the accessor's elements are zeros,
//   then its sparse substitutions). tinygltf reads such an accessor but
//   refuses a primitive whose indices name one ("invalid bufferView"). The
//   primitive's indices are taken out of the document before tinygltf
//   parses it and put back on the model after (IndicesWithoutView below);
//   the accessor itself is read as any other (scene/gltf_accessor.h).
const char* const kTolerated[] = {"'inverseBindMatrices' property is missing in Skin."};

// Primitives whose indices accessor has no bufferView: (mesh, primitive) -> that accessor.
using IndicesWithoutView = std::map<std::pair<std::size_t, std::size_t>, int>;

// Takes those primitives' "indices" out of the document; what it took.
IndicesWithoutView removeIndicesWithoutView(nlohmann::json& document) {
  IndicesWithoutView taken;
  const auto meshes = document.find("meshes");
  const auto accessors = document.find("accessors");
  if (meshes == document.end() || !meshes->is_array() || accessors == document.end() || !accessors->is_array()) return taken;
  for (std::size_t m = 0; m < meshes->size(); ++m) {
    nlohmann::json& mesh = (*meshes)[m];
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
    nlohmann::json& primitives = mesh["primitives"];
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      nlohmann::json& primitive = primitives[p];
      if (!primitive.is_object() || !primitive.contains("indices") || !primitive["indices"].is_number_unsigned()) continue;
      const std::uint64_t a = primitive["indices"].get<std::uint64_t>();
      if (a >= accessors->size() || !(*accessors)[a].is_object() || (*accessors)[a].contains("bufferView")) continue;
      taken[{m, p}] = static_cast<int>(a);
      primitive.erase("indices");
    }
  }
  return taken;
}

// A buffer without a uri holds no data, except a GLB's buffers[0], which is
// its BIN chunk. glTF allows one that nothing reads (a placeholder);
// tinygltf 2.7 refuses it in a .gltf ("'uri' is missing") and copies the
// BIN chunk into it in a GLB (refusing it when it is longer). Each unused
// one is handed to tinygltf as one zero byte from a data: URI; one that a
// bufferView lies in is refused, naming the bufferView and what reads it.
// True when it changed the document.
bool replacePlaceholderBuffers(const std::string& path, nlohmann::json& document, bool binary) {
  const auto buffers = document.find("buffers");
  if (buffers == document.end() || !buffers->is_array()) return false;
  const auto array = [&](const char* key) -> const nlohmann::json* {
    const auto found = document.find(key);
    return found != document.end() && found->is_array() ? &*found : nullptr;
  };
  const auto refersTo = [](const nlohmann::json& object, const char* key, std::size_t index) {
    if (!object.is_object()) return false;
    const auto found = object.find(key);
    return found != object.end() && found->is_number_unsigned() && found->get<std::uint64_t>() == index;
  };
  // What reads bufferViews[v]: an accessor (its own bufferView or its sparse parts) or an image; empty for nothing.
  const auto readerOf = [&](std::size_t v) -> std::string {
    if (const nlohmann::json* accessors = array("accessors"))
      for (std::size_t a = 0; a < accessors->size(); ++a) {
        const nlohmann::json& accessor = (*accessors)[a];
        if (refersTo(accessor, "bufferView", v)) return at("accessors", a);
        if (!accessor.is_object() || !accessor.contains("sparse") || !accessor["sparse"].is_object()) continue;
        for (const char* part : {"indices", "values"})
          if (accessor["sparse"].contains(part) && refersTo(accessor["sparse"][part], "bufferView", v))
            return at("accessors", a) + ".sparse." + part;
      }
    if (const nlohmann::json* images = array("images"))
      for (std::size_t i = 0; i < images->size(); ++i)
        if (refersTo((*images)[i], "bufferView", v)) return at("images", i);
    return {};
  };
  bool changed = false;
  for (std::size_t b = binary ? 1 : 0; b < buffers->size(); ++b) {
    nlohmann::json& buffer = (*buffers)[b];
    if (!buffer.is_object() || buffer.contains("uri")) continue;
    if (const nlohmann::json* views = array("bufferViews"))
      for (std::size_t v = 0; v < views->size(); ++v) {
        if (!refersTo((*views)[v], "buffer", b)) continue;
        const std::string reader = readerOf(v);
        throw Error(path + ": " + at("buffers", b) + ": has no uri, so it holds no data, but " + at("bufferViews", v) + " lies in it" +
                    (reader.empty() ? std::string() : " and " + reader + " reads that bufferView"));
      }
    buffer["uri"] = "data:application/octet-stream;base64,AA==";
    buffer["byteLength"] = 1;
    changed = true;
  }
  return changed;
}

// Removes the animation channels with no target node; true when it removed any.
bool removeChannelsWithoutNode(nlohmann::json& document, Warnings& warnings) {
  bool removed = false;
  const auto animations = document.find("animations");
  if (animations == document.end() || !animations->is_array()) return false;
  for (std::size_t a = 0; a < animations->size(); ++a) {
    nlohmann::json& animation = (*animations)[a];
    if (!animation.is_object() || !animation.contains("channels") || !animation["channels"].is_array()) continue;
    nlohmann::json& channels = animation["channels"];
    nlohmann::json kept = nlohmann::json::array();
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const nlohmann::json& channel = channels[c];
      const bool hasNode = channel.is_object() && channel.contains("target") && channel["target"].is_object() && channel["target"].contains("node");
      if (hasNode || !channel.is_object() || !channel.contains("target")) {
        kept.push_back(channel);  // a channel without target at all is tinygltf's to refuse: glTF requires target
        continue;
      }
      warnings.push_back(at("animations", a) + ".channels[" + std::to_string(c) +
                         "]: no target node (an extension names what it animates); ignored, facet does not animate");
      removed = true;
    }
    channels = std::move(kept);
  }
  return removed;
}

// A line of tinygltf's, which may hold text from the file (a URI, a name):
// its first line only, control and non-ASCII bytes escaped, at most 200 bytes.
std::string tinygltfLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  const auto newline = text.find('\n');
  const bool more = newline != std::string::npos;
  if (more) text.resize(newline);
  std::string line;
  for (std::size_t i = 0; i < text.size() && line.size() < 200; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      line += static_cast<char>(c);
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      line += escaped;
    }
  }
  if (line.size() >= 200) line += "...";
  return more ? line + " (and more)" : line;
}

}  // namespace

// [SECTION] loadGltf

Scene loadGltf(const std::string& path) {
  namespace fs = std::filesystem;
  const std::string bytes = readFile(path, kMaxGltfFileBytes);
  std::error_code ec;
  const std::string folder = fs::weakly_canonical(fs::absolute(path).parent_path(), ec).string();
  Scene scene = loadGltfFromMemory(bytes, path, folder.empty() ? "/" : folder);
  scene.files.insert(scene.files.begin(), path);
  return scene;
}

Scene loadGltfFromMemory(const std::string& bytes, const std::string& path, const std::string& assetFolder) {
  namespace fs = std::filesystem;
  const std::string extension = fs::path(path).extension().string();
  const GltfLayout layout = gltfLayout(path, bytes, extension == ".glb" || extension == ".GLB");
  const std::string_view json = std::string_view(bytes).substr(layout.jsonOffset, layout.jsonLength);
  if (jsonDepth(json.data(), json.size()) > kMaxGltfJsonDepth)
    throw Error(path + ": JSON nested deeper than " + std::to_string(kMaxGltfJsonDepth) + " levels");
  Warnings warnings;
  std::string repaired;  // the bytes tinygltf parses when the document or the GLB layout had to change
  IndicesWithoutView indicesWithoutView;  // put back on the model once tinygltf has parsed it
  {
    nlohmann::json document = parseGltfJson(path, json);
    checkRequiredExtensions(path, document);
    checkGltfDocument(path, document, assetFolder, kMaxGltfFileBytes);
    indicesWithoutView = removeIndicesWithoutView(document);
    const bool placeholders = replacePlaceholderBuffers(path, document, layout.binary);
    const bool changed = removeChannelsWithoutNode(document, warnings) || !indicesWithoutView.empty() || placeholders;
    const std::string_view bin = layout.hasBin ? std::string_view(bytes).substr(layout.binOffset, layout.binLength) : std::string_view();
    if (changed) repaired = layout.binary ? glbBytes(document.dump(), bin) : document.dump();
    else if (!layout.plain) repaired = glbBytes(std::string(json), bin);
  }
  const std::string& parsed = repaired.empty() ? bytes : repaired;
  const bool binary = layout.binary;

  AssetFolder folder;
  folder.root = assetFolder;
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(folderCallbacks<tinygltf::FsCallbacks>(folder));
  tinygltf::Model model;
  MemoryBudget sceneBudget(kSceneMemoryBudget, "scene budget");
  ImageLoading images;
  images.model = &model;
  images.budget = &sceneBudget;
  loader.SetImageLoader(loadImage, &images);
  std::string err, warn;
  bool ok = false;
  try {
    const auto* data = reinterpret_cast<const unsigned char*>(parsed.data());
    const std::string base = folder.root.string();
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, static_cast<unsigned int>(parsed.size()), base)
                : loader.LoadASCIIFromString(&model, &err, &warn, parsed.data(), static_cast<unsigned int>(parsed.size()), base);
  } catch (const std::exception& e) {
    throw Error(path + ": glTF parser failed (" + e.what() + ")");
  } catch (...) {
    throw Error(path + ": glTF parser failed");
  }
  if (images.failure) throw Error(path + ": " + images.failure->what());
  for (const char* tolerated : kTolerated)  // what tinygltf reports that glTF allows
    for (auto at = err.find(tolerated); at != std::string::npos; at = err.find(tolerated)) {
      std::size_t end = at + std::strlen(tolerated);
      if (end < err.size() && err[end] == '\n') ++end;
      err.erase(at, end - at);
    }
  if (!ok || !err.empty()) throw Error(path + ": " + (err.empty() ? std::string("not a valid glTF file") : tinygltfLine(err)));
  if (model.asset.version.empty() || model.asset.version[0] != '2')
    throw Error(path + ": asset.version " + quoteInput(model.asset.version) + " is not glTF 2.x (UNKNOWN_ASSET_MAJOR_VERSION)");
  for (const std::string& required : model.extensionsRequired)
    if (!kSupportedExtensions.count(required))
      throw Error(path + ": requires extension " + quoteInput(required) + ", which facet does not support");
  for (const auto& [primitive, accessor] : indicesWithoutView)
    if (primitive.first < model.meshes.size() && primitive.second < model.meshes[primitive.first].primitives.size())
      model.meshes[primitive.first].primitives[primitive.second].indices = accessor;

  Scene scene;
  scene.source = path;
  scene.files = std::move(folder.read);
  for (std::string line; !warn.empty();) {  // tinygltf's own warnings, one per line
    const auto newline = warn.find('\n');
    line = warn.substr(0, newline);
    warn = newline == std::string::npos ? std::string() : warn.substr(newline + 1);
    if (!line.empty()) warnings.push_back(tinygltfLine(line));
  }
  for (const std::string& used : model.extensionsUsed)
    if (!kSupportedExtensions.count(used)) warnings.push_back("extension " + quoteInput(used) + " is not supported; ignored");

  // Meshes first: textures decode only once everything has been priced.
  std::vector<std::vector<int>> meshTable;
  try {
    meshTable = convertMeshes(model, sceneBudget, scene, warnings);
    convertTextures(model, images.encoded, sceneBudget, scene, warnings);
    convertMaterials(model, scene, warnings);
    warnUnreadTextures(scene, meshTable, warnings);
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }

  // Roots: the default scene's nodes, else the first scene's, else every node without a parent.
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    int chosen = model.defaultScene;
    if (chosen < 0 || static_cast<std::size_t>(chosen) >= model.scenes.size()) chosen = 0;
    roots = model.scenes[static_cast<std::size_t>(chosen)].nodes;
  } else {
    std::vector<char> isChild(model.nodes.size(), 0);
    for (const tinygltf::Node& node : model.nodes)
      for (int child : node.children)
        if (child >= 0 && static_cast<std::size_t>(child) < isChild.size()) isChild[static_cast<std::size_t>(child)] = 1;
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
      if (!isChild[n]) roots.push_back(static_cast<int>(n));
    if (!model.nodes.empty()) warnings.push_back("the file has no scenes; drawing every root node");
  }
  NodeWalker walker{model, scene, warnings, meshTable, std::vector<char>(model.nodes.size(), 0), {}};
  try {
    for (int root : roots) walker.visit(root, glm::mat4(1.0f), 0);
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  readAnimations(model, walker.animatedIndex, sceneBudget, scene.animation, warnings);
  if (scene.instances.empty()) warnings.push_back("no triangles to draw");
  scene.warnings = std::move(warnings);
  return scene;
}

}  // namespace facet
