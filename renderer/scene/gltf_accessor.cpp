#include "scene/gltf_accessor.h"
#include "vocabulary/limits.h"

#include <cstring>
#include <algorithm>
#include <limits>
#include <optional>

#include <tiny_gltf.h>

namespace facet {
namespace {

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

template <class T>
T load(const unsigned char* p) {
  T value;
  std::memcpy(&value, p, sizeof value);
  return value;
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

// The bytes of bufferViews[v], checked against the buffer as read (the
// document checks did it on the JSON already; this holds for a Model made
// any other way too).
struct ViewBytes {
  const unsigned char* data = nullptr;
  std::uint64_t length = 0;
  std::uint64_t byteStride = 0;
};

ViewBytes viewBytes(const tinygltf::Model& model, int v, const std::string& user) {
  if (v < 0 || static_cast<std::size_t>(v) >= model.bufferViews.size())
    throw AccessorError{user + ": bufferView " + std::to_string(v) + " does not exist (UNRESOLVED_REFERENCE)"};
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(v)];
  const std::string viewName = "bufferViews[" + std::to_string(v) + "]";
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
    throw AccessorError{viewName + ": buffer " + std::to_string(view.buffer) + " does not exist (UNRESOLVED_REFERENCE)"};
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  const std::uint64_t viewStart = view.byteOffset, viewLength = view.byteLength;
  if (viewStart > buffer.size() || viewLength > buffer.size() - viewStart)
    throw AccessorError{viewName + ": byteOffset " + std::to_string(viewStart) + " + byteLength " + std::to_string(viewLength) +
                        " runs past its buffer of " + std::to_string(buffer.size()) + " bytes (BUFFER_VIEW_TOO_LONG)"};
  return {buffer.data() + viewStart, viewLength, view.byteStride};
}

// `count` tightly packed elements of `elementSize` bytes at `offset` in a view.
const unsigned char* packedRun(const ViewBytes& view, std::int64_t offset, std::uint64_t count, std::uint64_t elementSize, int componentSize,
                               const std::string& what) {
  if (offset < 0) throw AccessorError{what + ": byteOffset " + std::to_string(offset) + " is negative"};
  const auto start = static_cast<std::uint64_t>(offset);
  if (start % static_cast<std::uint64_t>(componentSize) != 0)
    throw AccessorError{what + ": byteOffset " + std::to_string(start) + " is not a multiple of the component size (ACCESSOR_OFFSET_ALIGNMENT)"};
  const std::uint64_t needed = count * elementSize;  // count ≤ 2^28, elementSize ≤ 64: no overflow
  if (start > view.length || needed > view.length - start)
    throw AccessorError{what + ": needs " + std::to_string(start + needed) + " bytes but its bufferView has " + std::to_string(view.length) +
                        " (ACCESSOR_TOO_LONG)"};
  return view.data + start;
}

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

  ElementSpan span;
  span.count = a.count;
  span.componentType = a.componentType;
  span.normalized = a.normalized;
  const std::uint64_t elementSize = static_cast<std::uint64_t>(size) * static_cast<std::uint64_t>(components);
  span.stride = elementSize;
  if (a.bufferView < 0) return span;  // zeros (glTF: "When undefined, the accessor MUST be initialized with zeros")

  const ViewBytes view = viewBytes(model, a.bufferView, name(index));
  if (view.byteStride != 0) {
    if (view.byteStride < elementSize || view.byteStride > 252 || view.byteStride % static_cast<std::size_t>(size) != 0)
      throw AccessorError{"bufferViews[" + std::to_string(a.bufferView) + "]: byteStride " + std::to_string(view.byteStride) + " is invalid for " +
                          name(index) + " (BUFFER_VIEW_INVALID_BYTE_STRIDE)"};
    span.stride = view.byteStride;
  }
  const std::uint64_t offset = a.byteOffset;
  if (offset % static_cast<std::uint64_t>(size) != 0)
    throw AccessorError{name(index) + ": byteOffset " + std::to_string(offset) + " is not a multiple of the component size (ACCESSOR_OFFSET_ALIGNMENT)"};
  // All sizes fit in 64 bits: byteOffset/byteLength are size_t, count ≤ 2^28, stride ≤ 2^8.
  const std::uint64_t needed = offset + span.stride * (span.count - 1) + elementSize;
  if (offset > view.length || needed > view.length)
    throw AccessorError{name(index) + ": needs " + std::to_string(needed) + " bytes but bufferViews[" + std::to_string(a.bufferView) + "] has " +
                        std::to_string(view.length) + " (ACCESSOR_TOO_LONG)"};
  span.data = view.data + offset;
  return span;
}

// glTF 2.0, 3.6.2.3 "Sparse Accessors": `count` element indices (strictly
// increasing, below the accessor's count) and as many tightly packed values
// that replace those elements of the base (its bufferView, or zeros).
struct SparseSpan {
  std::vector<std::uint32_t> indices;
  ElementSpan values;
};

SparseSpan locateSparse(const tinygltf::Model& model, int index, const ElementSpan& base) {
  const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
  SparseSpan sparse;
  const std::string what = name(index) + ".sparse";
  if (a.sparse.count < 1 || static_cast<std::uint64_t>(a.sparse.count) > base.count)
    throw AccessorError{what + ": count " + std::to_string(a.sparse.count) + " is not in [1, " + std::to_string(base.count) + "]"};
  const auto count = static_cast<std::uint64_t>(a.sparse.count);
  const int indexSize = componentSize(a.sparse.indices.componentType);
  if (a.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && a.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      a.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    throw AccessorError{what + ".indices: componentType " + std::to_string(a.sparse.indices.componentType) + " is not UNSIGNED_BYTE/SHORT/INT"};
  const unsigned char* p = packedRun(viewBytes(model, a.sparse.indices.bufferView, what + ".indices"), a.sparse.indices.byteOffset, count,
                                     static_cast<std::uint64_t>(indexSize), indexSize, what + ".indices");
  sparse.indices.resize(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    std::uint32_t e = 0;
    if (indexSize == 1) e = p[i];
    else if (indexSize == 2) e = load<std::uint16_t>(p + 2 * i);
    else e = load<std::uint32_t>(p + 4 * i);
    if (e >= base.count || (i > 0 && e <= sparse.indices[i - 1]))
      throw AccessorError{what + ".indices: element " + std::to_string(i) + " is " + std::to_string(e) +
                          (e >= base.count ? ", past the accessor's " + std::to_string(base.count) + " elements (ACCESSOR_SPARSE_INDEX_OOB)"
                                           : ", not above the one before (ACCESSOR_SPARSE_INDICES_NON_INCREASING)")};
    sparse.indices[i] = e;
  }
  sparse.values = base;
  sparse.values.count = count;
  const int size = componentSize(a.componentType);
  sparse.values.stride = static_cast<std::uint64_t>(size) * static_cast<std::uint64_t>(componentCount(a.type));  // tightly packed
  sparse.values.data = packedRun(viewBytes(model, a.sparse.values.bufferView, what + ".values"), a.sparse.values.byteOffset, count,
                                 sparse.values.stride, size, what + ".values");
  return sparse;
}

// One component as float, honouring `normalized` with glTF's formulas
// (3.11): c / 255 and c / 65535 unsigned, max(c / 127, -1) and
// max(c / 32767, -1) signed; an integer that is not normalized is its value.
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
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float v = static_cast<float>(load<std::int8_t>(p + c));
      return s.normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const float v = static_cast<float>(load<std::int16_t>(p + 2 * c));
      return s.normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    default: return 0.0f;
  }
}

// The component formats an attribute may have beside FLOAT: the core's
// normalized unsigned ones (texture coordinates, colours), and those
// KHR_mesh_quantization adds (normalized signed ones, and integers that are
// not normalized, read as their values).
struct Formats {
  bool signedNormalized = false, unsignedNormalized = false, integers = false;
};

bool accepts(const ElementSpan& s, Formats f) {
  switch (s.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return true;
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_SHORT: return s.normalized ? f.signedNormalized : f.integers;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return s.normalized ? f.unsignedNormalized : f.integers;
    default: return false;
  }
}

// KHR_mesh_quantization's formats per attribute.
constexpr Formats kPositionFormats{true, true, true};   // every byte and short, normalized or not
constexpr Formats kDirectionFormats{true, false, false};  // NORMAL, TANGENT: normalized BYTE and SHORT
constexpr Formats kTexcoordFormats{true, true, true};   // every byte and short, normalized or not

// Every element of the accessor through `element(span, e)`, the base first,
// then its sparse substitutions.
template <class T, class Element>
std::vector<T> readAll(const tinygltf::Model& model, int accessor, const ElementSpan& s, Element element) {
  std::optional<SparseSpan> sparse;
  if (model.accessors[static_cast<std::size_t>(accessor)].sparse.isSparse) sparse = locateSparse(model, accessor, s);
  std::vector<T> out(s.count);
  for (std::uint64_t e = 0; e < s.count; ++e) out[e] = element(s, e);
  if (sparse)
    for (std::uint64_t i = 0; i < sparse->values.count; ++i) out[sparse->indices[i]] = element(sparse->values, i);
  return out;
}

}  // namespace

std::uint64_t accessorCount(const tinygltf::Model& model, int accessor) {
  if (accessor < 0 || static_cast<std::size_t>(accessor) >= model.accessors.size()) return 0;
  return std::min<std::uint64_t>(model.accessors[static_cast<std::size_t>(accessor)].count, kMaxAccessorCount);
}

std::vector<glm::vec3> readPositions(const tinygltf::Model& model, int accessor) {
  const ElementSpan s = locate(model, accessor, 3);
  if (!accepts(s, kPositionFormats))
    throw AccessorError{name(accessor) + ": componentType " + std::to_string(s.componentType) +
                        " is not FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT (MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT)"};
  return readAll<glm::vec3>(model, accessor, s, [](const ElementSpan& span, std::uint64_t e) {
    return glm::vec3(component(span, e, 0), component(span, e, 1), component(span, e, 2));
  });
}

std::vector<glm::vec3> readNormals(const tinygltf::Model& model, int accessor) {
  const ElementSpan s = locate(model, accessor, 3);
  if (!accepts(s, kDirectionFormats))
    throw AccessorError{name(accessor) + ": normals must be FLOAT or normalized BYTE/SHORT (MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT)"};
  return readAll<glm::vec3>(model, accessor, s, [](const ElementSpan& span, std::uint64_t e) {
    return glm::vec3(component(span, e, 0), component(span, e, 1), component(span, e, 2));
  });
}

std::vector<glm::vec4> readTangents(const tinygltf::Model& model, int accessor) {
  const ElementSpan s = locate(model, accessor, 4);
  if (!accepts(s, kDirectionFormats))
    throw AccessorError{name(accessor) + ": tangents must be FLOAT or normalized BYTE/SHORT (MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT)"};
  return readAll<glm::vec4>(model, accessor, s, [](const ElementSpan& span, std::uint64_t e) {
    return glm::vec4(component(span, e, 0), component(span, e, 1), component(span, e, 2), component(span, e, 3));
  });
}

std::vector<glm::vec3> readVec3(const tinygltf::Model& model, int accessor) {
  const ElementSpan s = locate(model, accessor, 3);
  if (s.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    throw AccessorError{name(accessor) + ": componentType " + std::to_string(s.componentType) + " is not FLOAT (MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT)"};
  return readAll<glm::vec3>(model, accessor, s, [](const ElementSpan& span, std::uint64_t e) {
    return glm::vec3(component(span, e, 0), component(span, e, 1), component(span, e, 2));
  });
}

std::vector<glm::vec4> readVec4(const tinygltf::Model& model, int accessor) {
  const ElementSpan s = locate(model, accessor, 4);
  if (s.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    throw AccessorError{name(accessor) + ": componentType " + std::to_string(s.componentType) + " is not FLOAT (MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT)"};
  return readAll<glm::vec4>(model, accessor, s, [](const ElementSpan& span, std::uint64_t e) {
    return glm::vec4(component(span, e, 0), component(span, e, 1), component(span, e, 2), component(span, e, 3));
  });
}

std::vector<float> readScalars(const tinygltf::Model& model, int accessor) {
  const ElementSpan s = locate(model, accessor, 1);
  if (s.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    throw AccessorError{name(accessor) + ": componentType " + std::to_string(s.componentType) + " is not FLOAT (ANIMATION_SAMPLER_INPUT_ACCESSOR_INVALID_FORMAT)"};
  return readAll<float>(model, accessor, s, [](const ElementSpan& span, std::uint64_t e) { return component(span, e, 0); });
}

std::vector<glm::vec2> readVec2(const tinygltf::Model& model, int accessor) {
  const ElementSpan s = locate(model, accessor, 2);
  if (!accepts(s, kTexcoordFormats))
    throw AccessorError{name(accessor) + ": texture coordinates must be FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT (MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT)"};
  return readAll<glm::vec2>(model, accessor, s,
                            [](const ElementSpan& span, std::uint64_t e) { return glm::vec2(component(span, e, 0), component(span, e, 1)); });
}

std::vector<glm::vec4> readColors(const tinygltf::Model& model, int accessor) {
  const int type = accessor >= 0 && static_cast<std::size_t>(accessor) < model.accessors.size() ? model.accessors[static_cast<std::size_t>(accessor)].type : 0;
  const ElementSpan s = locate(model, accessor, type == TINYGLTF_TYPE_VEC3 ? 3 : 4);
  const bool floatOrUnorm = s.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                            (s.normalized && (s.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                              s.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT));
  if (!floatOrUnorm)
    throw AccessorError{name(accessor) + ": colours must be FLOAT or normalized UNSIGNED_BYTE/SHORT (MESH_PRIMITIVE_ATTRIBUTES_ACCESSOR_INVALID_FORMAT)"};
  const bool rgb = type == TINYGLTF_TYPE_VEC3;
  return readAll<glm::vec4>(model, accessor, s, [rgb](const ElementSpan& span, std::uint64_t e) {
    return glm::vec4(component(span, e, 0), component(span, e, 1), component(span, e, 2), rgb ? 1.0f : component(span, e, 3));
  });
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessor) {
  const ElementSpan s = locate(model, accessor, 1);
  if (s.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && s.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      s.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    throw AccessorError{name(accessor) + ": index componentType " + std::to_string(s.componentType) +
                        " is not UNSIGNED_BYTE/SHORT/INT (MESH_PRIMITIVE_INDICES_ACCESSOR_INVALID_FORMAT)"};
  return readAll<std::uint32_t>(model, accessor, s, [](const ElementSpan& span, std::uint64_t e) -> std::uint32_t {
    if (!span.data) return 0u;
    const unsigned char* p = span.data + e * span.stride;
    switch (span.componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<std::uint16_t>(p);
      default: return load<std::uint32_t>(p);
    }
  });
}

}  // namespace facet
