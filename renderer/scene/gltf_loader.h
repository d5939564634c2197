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

// The same from bytes in memory (a .gltf's JSON or a whole .glb): `name`
// stands for the file in messages; external URIs resolve inside `folder`
// only, and an empty `folder` resolves none. The fuzzer's entry point.
Scene loadGltfFromMemory(const std::string& bytes, const std::string& name, const std::string& folder);

}  // namespace facet
