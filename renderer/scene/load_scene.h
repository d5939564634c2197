#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace facet {

// The scene behind a command line's positional argument:
//   ""  or "builtin:default"   the built-in default scene
//   "builtin:cornell"          the Cornell box (the ray tracer's chapter scene)
//   "builtin:fountain"         the default scene with a particle fountain on its ground
//   "builtin:NAME"             one procedural primitive on its own (sphere,
//                              cube, plane, cylinder, torus), with no camera
//                              or light of its own (auto ones frame and light it)
//   "builtin:NAME+ground"      the primitive above a 6 m ground that receives its shadow
//   a volume (.nrrd, .nhdr, .nii, .nii.gz, builtin:marschner-lobb)
//                              an empty scene holding it (volume/load_volume.h)
//   anything else              a glTF 2.0 file (.gltf, .glb)
Scene loadScene(const std::string& path);

// The NAMEs of builtin:NAME.
std::vector<std::string_view> builtinSceneNames();

}  // namespace facet
