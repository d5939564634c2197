#pragma once
#include <string>

#include "scene/scene.h"

namespace facet {

// The scene behind a command line's positional argument: the built-in
// default scene for an empty path, otherwise a glTF 2.0 file (.gltf, .glb).
Scene loadScene(const std::string& path);

}  // namespace facet
