#pragma once
// A mesh written out as a glTF 2.0 file (marching cubes' iso-surface, so
// that other tools can open it): positions, normals and indices in one
// buffer embedded as a base64 data URI, one node placing it.
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace facet {

// Writes `mesh` (positions, normals, indices) placed by worldFromModel with
// an opaque material of `color` (linear RGB), atomically: a failure leaves
// no file. Throws facet::Error naming the file.
void writeMeshGltf(const Mesh& mesh, const glm::mat4& worldFromModel, glm::vec3 color, const std::string& path);

}  // namespace facet
