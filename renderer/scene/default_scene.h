#pragma once
#include "scene/scene.h"

namespace facet {

// The scene rendered when no file is given: a ground plane, a sphere, a cube,
// a cylinder and a torus of different materials, one shadow-casting point
// light and a camera that frames them. Built in code; no file needed.
Scene makeDefaultScene();

}  // namespace facet
