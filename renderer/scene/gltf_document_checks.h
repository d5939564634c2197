#pragma once
// The rules of glTF 2.0 that facet checks on a file's JSON document before
// tinygltf reads it, because tinygltf does not, and breaking them would
// make a later read go out of bounds, loop, or draw something the file does
// not mean:
//   - an image's bufferView lies inside its buffer (tinygltf hands it to
//     the image decoder unchecked; accessors' bufferViews, sparse ones
//     included, are checked where they are read, gltf_accessor.h);
//   - buffer and image URIs name regular files inside the scene's folder;
//   - the node hierarchy is a set of disjoint trees: a node has at most one
//     parent, no node is its own ancestor, scene roots have no parent
//     (glTF 2.0, 3.5.3) — a DAG would be walked once per path;
//   - the properties facet reads have glTF's JSON types (arrays of objects,
//     string names, a "scene" that exists, primitives with attributes,
//     material objects and numbers, extensions that are objects): tinygltf
//     reads a mistyped one as absent, and the file would draw as something else;
//   - textures name samplers that exist;
//   - KHR_lights_punctual lights have a known type and, for spots,
//     0 ≤ innerConeAngle < outerConeAngle ≤ π/2.
// Each failure throws facet::Error with one line naming the file and the
// object (e.g. "scene.gltf: nodes[7]: is a child of both nodes[2] and nodes[5] ...").
#include <string>

#include <nlohmann/json.hpp>

namespace facet {

// `folder`: the canonical folder external URIs resolve in; empty: none are
// read (loadGltfFromMemory without a folder), and a document naming one is
// refused. `maxFileBytes`: the largest external file read.
void checkGltfDocument(const std::string& path, const nlohmann::json& document, const std::string& folder, std::uint64_t maxFileBytes);

}  // namespace facet
