// A mesh as a self-contained glTF 2.0 file.
#include "scene/gltf_writer.h"

#include <cstdint>
#include <cstring>
#include <limits>

#include <nlohmann/json.hpp>

#include "common/atomic_file.h"
#include "common/error.h"

namespace facet {
namespace {

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = (std::uint32_t{bytes[i]} << 16) | (i + 1 < bytes.size() ? std::uint32_t{bytes[i + 1]} << 8 : 0u) |
                            (i + 2 < bytes.size() ? std::uint32_t{bytes[i + 2]} : 0u);
    out += kDigits[(n >> 18) & 63];
    out += kDigits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
  }
  return out;
}

template <class T>
void append(std::vector<std::uint8_t>& out, const std::vector<T>& values) {
  const std::size_t at = out.size();
  out.resize(at + values.size() * sizeof(T));
  if (!values.empty()) std::memcpy(out.data() + at, values.data(), values.size() * sizeof(T));
}

}  // namespace

void writeMeshGltf(const Mesh& mesh, const glm::mat4& worldFromModel, glm::vec3 color, const std::string& path) {
  using nlohmann::json;
  if (mesh.positions.empty() || mesh.indices.empty()) throw Error(path + ": the mesh is empty; nothing to write");
  std::vector<std::uint8_t> buffer;
  append(buffer, mesh.positions);
  append(buffer, mesh.normals);
  append(buffer, mesh.indices);
  const std::size_t positionBytes = mesh.positions.size() * sizeof(glm::vec3);
  const std::size_t normalBytes = mesh.normals.size() * sizeof(glm::vec3);
  Bounds bounds;
  for (const glm::vec3& p : mesh.positions) bounds.include(p);
  json matrix = json::array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) matrix.push_back(worldFromModel[c][r]);  // column-major, as glTF stores it
  const json doc = {
      {"asset", {{"version", "2.0"}, {"generator", "facet"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"name", mesh.name}, {"mesh", 0}, {"matrix", matrix}}}},
      {"materials", {{{"name", mesh.name}, {"doubleSided", true},
                      {"pbrMetallicRoughness", {{"baseColorFactor", {color.r, color.g, color.b, 1.0f}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}}}}},
      {"meshes", {{{"name", mesh.name}, {"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}, {"material", 0}}}}}}},
      {"buffers", {{{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positionBytes}, {"target", 34962}},
                       {{"buffer", 0}, {"byteOffset", positionBytes}, {"byteLength", normalBytes}, {"target", 34962}},
                       {{"buffer", 0}, {"byteOffset", positionBytes + normalBytes}, {"byteLength", mesh.indices.size() * 4}, {"target", 34963}}}},
      {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", mesh.positions.size()}, {"type", "VEC3"},
                      {"min", {bounds.min.x, bounds.min.y, bounds.min.z}}, {"max", {bounds.max.x, bounds.max.y, bounds.max.z}}},
                     {{"bufferView", 1}, {"componentType", 5126}, {"count", mesh.normals.size()}, {"type", "VEC3"}},
                     {{"bufferView", 2}, {"componentType", 5125}, {"count", mesh.indices.size()}, {"type", "SCALAR"}}}},
  };
  writeFileAtomically(path, std::string_view(doc.dump()));
}

}  // namespace facet
