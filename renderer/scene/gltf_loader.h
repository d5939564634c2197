#pragma once
#include <string>

#include "scene/scene.h"

namespace facet {

// Loads a glTF 2.0 file (.gltf with its buffers and images, or .glb) into a
// Scene: triangle primitives (lists, strips and fans), metallic-roughness
// materials with base-colour textures, KHR_lights_punctual lights and
// cameras, node transforms flattened to world matrices.
//
// What it skips or repairs (non-triangle primitives, unsupported extensions,
// missing normals, invalid triangles) is recorded in Scene::warnings. A file
// that cannot be drawn sensibly throws facet::Error with one line that names
// the file, the glTF object and the problem.
Scene loadGltf(const std::string& path);

}  // namespace facet
