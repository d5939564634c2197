#pragma once
// Reading glTF accessors with every range checked. tinygltf trusts what a file
// says about offsets, strides and counts; these functions do not. Problems
// are reported with the glTF-Validator's names (ACCESSOR_TOO_LONG, ...).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace tinygltf {
class Model;
}

namespace facet {

// Thrown for a problem in one accessor; the loader decides whether that
// skips a primitive or refuses the file. what() starts with "accessors[N]".
struct AccessorError {
  std::string message;
};

// Sparse accessors (glTF 2.0, 3.6.2.3) are read with their indices and
// values held to their bufferViews as the base is.

// An accessor's element count as the file states it (0 when the accessor
// does not exist; at most the limit reading it allows), to price what
// reading it allocates before it is read.
std::uint64_t accessorCount(const tinygltf::Model& model, int accessor);

// Mesh attributes take KHR_mesh_quantization's formats besides FLOAT:
// normalized integers become floats by glTF's formulas (c / 255, c / 65535,
// max(c / 127, -1), max(c / 32767, -1)), other integers are their values.
// VEC3 POSITION: float, or (normalized or not) byte/short, signed or unsigned.
std::vector<glm::vec3> readPositions(const tinygltf::Model& model, int accessor);
// VEC3 NORMAL: float, or normalized signed byte/short.
std::vector<glm::vec3> readNormals(const tinygltf::Model& model, int accessor);
// VEC4 TANGENT: float, or normalized signed byte/short.
std::vector<glm::vec4> readTangents(const tinygltf::Model& model, int accessor);
// Float VEC3 (an animation's translations and scales).
std::vector<glm::vec3> readVec3(const tinygltf::Model& model, int accessor);
// Float VEC4 (an animation's rotations).
std::vector<glm::vec4> readVec4(const tinygltf::Model& model, int accessor);
// VEC2 TEXCOORD_n: float, or (normalized or not) byte/short, signed or unsigned.
std::vector<glm::vec2> readVec2(const tinygltf::Model& model, int accessor);
// VEC3 or VEC4 of float, or normalized unsigned byte/short (COLOR_n), as
// linear RGBA: VEC3 gets alpha 1.
std::vector<glm::vec4> readColors(const tinygltf::Model& model, int accessor);
// SCALAR float (an animation sampler's key times).
std::vector<float> readScalars(const tinygltf::Model& model, int accessor);
// SCALAR unsigned byte/short/int (indices).
std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessor);

}  // namespace facet
