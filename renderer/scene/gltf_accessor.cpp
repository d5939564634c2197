#include "scene/gltf_accessor.h"

#include <cstring>
#include <limits>

#include <tiny_gltf.h>

namespace facet {
namespace {

// No accessor in a file we accept holds more elements than this: it keeps a
// hostile count from turning into a huge allocation.
constexpr std::uint64_t kMaxAccessorCount = 1ull << 28;

std::string name(int accessor) { return "accessors[" + std::to_string(accessor) + "]"; }

int componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

// Where an accessor's elements are: element e starts at data + e * stride.
// data is null for an accessor with no bufferView (all zeros, per glTF).
struct ElementSpan {
  const unsigned char* data = nullptr;
  std::uint64_t stride = 0;
  std::uint64_t count = 0;
  int componentType = 0;
  bool normalized = false;
};

ElementSpan locate(const tinygltf::Model& model, int index, int wantedComponents) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
    throw AccessorError{name(index) + ": no such accessor (UNRESOLVED_REFERENCE)"};
  const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
  const int size = componentSize(a.componentType);
  const int components = componentCount(a.type);
  if (size == 0) throw AccessorError{name(index) + ": invalid componentType " + std::to_string(a.componentType)};
  if (components != wantedComponents)
    throw AccessorError{name(index) + ": has " + std::to_string(components) + " components per element, expected " +
                        std::to_string(wantedComponents) + " (ACCESSOR_INVALID_TYPE)"};
  if (a.count == 0) throw AccessorError{name(index) + ": count is 0"};
  if (a.count > kMaxAccessorCount)
    throw AccessorError{name(index) + ": count " + std::to_string(a.count) + " exceeds the limit of " + std::to_string(kMaxAccessorCount)};
  if (a.sparse.isSparse) throw AccessorError{name(index) + ": sparse accessors are not supported"};

  ElementSpan span;
  span.count = a.count;
  span.componentType = a.componentType;
  span.normalized = a.normalized;
  const std::uint64_t elementSize = static_cast<std::uint64_t>(size) * static_cast<std::uint64_t>(components);
  span.stride = elementSize;
  if (a.bufferView < 0) return span;  // zeros

  if (static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size())
    throw AccessorError{name(index) + ": bufferView " + std::to_string(a.bufferView) + " does not exist (UNRESOLVED_REFERENCE)"};
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const std::string viewName = "bufferViews[" + std::to_string(a.bufferView) + "]";
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
    throw AccessorError{viewName + ": buffer " + std::to_string(view.buffer) + " does not exist (UNRESOLVED_REFERENCE)"};
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  // All sizes fit in 64 bits: byteOffset/byteLength are size_t, count ≤ 2^28, stride ≤ 2^8.
  const std::uint64_t viewStart = view.byteOffset, viewLength = view.byteLength;
  if (viewStart > buffer.size() || viewLength > buffer.size() - viewStart)
    throw AccessorError{viewName + ": byteOffset " + std::to_string(viewStart) + " + byteLength " + std::to_string(viewLength) +
                        " runs past its buffer of " + std::to_string(buffer.size()) + " bytes (BUFFER_VIEW_TOO_LONG)"};
  if (view.byteStride != 0) {
    if (view.byteStride < elementSize || view.byteStride > 252 || view.byteStride % static_cast<std::size_t>(size) != 0)
      throw AccessorError{viewName + ": byteStride " + std::to_string(view.byteStride) + " is invalid for " + name(index) +
                          " (BUFFER_VIEW_INVALID_BYTE_STRIDE)"};
    span.stride = view.byteStride;
  }
  const std::uint64_t offset = a.byteOffset;
  if (offset % static_cast<std::uint64_t>(size) != 0)
    throw AccessorError{name(index) + ": byteOffset " + std::to_string(offset) + " is not a multiple of the component size (ACCESSOR_OFFSET_ALIGNMENT)"};
  const std::uint64_t needed = offset + span.stride * (span.count - 1) + elementSize;
  if (offset > viewLength || needed > viewLength)
    throw AccessorError{name(index) + ": needs " + std::to_string(needed) + " bytes but " + viewName + " has " +
                        std::to_string(viewLength) + " (ACCESSOR_TOO_LONG)"};
  span.data = buffer.data() + viewStart + offset;
  return span;
}

template <class T>
T load(const unsigned char* p) {
  T value;
  std::memcpy(&value, p, sizeof value);
  return value;
}

// One component as float, honouring `normalized` (glTF's formulas for unorm).
float component(const ElementSpan& s, std::uint64_t element, int c) {
  if (!s.data) return 0.0f;
  const unsigned char* p = s.data + element * s.stride;
  switch (s.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p + 4 * c);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const float v = static_cast<float>(p[c]);
      return s.normalized ? v / 255.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const float v = static_cast<float>(load<std::uint16_t>(p + 2 * c));
      return s.normalized ? v / 65535.0f : v;
    }
    default: return 0.0f;
  }
}

}  // namespace

std::vector<glm::vec3> readVec3(const tinygltf::Model& model, int accessor) {
  const ElementSpan s = locate(model, accessor, 3);
  if (s.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    throw AccessorError{name(accessor) + ": componentType " + std::to_string(s.componentType) + " is not FLOAT (MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT)"};
  std::vector<glm::vec3> out(s.count);
  for (std::uint64_t e = 0; e < s.count; ++e) out[e] = {component(s, e, 0), component(s, e, 1), component(s, e, 2)};
  return out;
}

std::vector<glm::vec2> readVec2(const tinygltf::Model& model, int accessor) {
  const ElementSpan s = locate(model, accessor, 2);
  const bool floatOrUnorm = s.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                            (s.normalized && (s.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                              s.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT));
  if (!floatOrUnorm)
    throw AccessorError{name(accessor) + ": texture coordinates must be FLOAT or normalized UNSIGNED_BYTE/SHORT (MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT)"};
  std::vector<glm::vec2> out(s.count);
  for (std::uint64_t e = 0; e < s.count; ++e) out[e] = {component(s, e, 0), component(s, e, 1)};
  return out;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessor) {
  const ElementSpan s = locate(model, accessor, 1);
  std::vector<std::uint32_t> out(s.count);
  for (std::uint64_t e = 0; e < s.count; ++e) {
    const unsigned char* p = s.data ? s.data + e * s.stride : nullptr;
    switch (s.componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: out[e] = p ? p[0] : 0u; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: out[e] = p ? load<std::uint16_t>(p) : 0u; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: out[e] = p ? load<std::uint32_t>(p) : 0u; break;
      default:
        throw AccessorError{name(accessor) + ": index componentType " + std::to_string(s.componentType) +
                            " is not UNSIGNED_BYTE/SHORT/INT (MESH_PRIMITIVE_INDICES_ACCESSOR_INVALID_FORMAT)"};
    }
  }
  return out;
}

}  // namespace facet
