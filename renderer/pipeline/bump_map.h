#pragma once
// Bump mapping (renderer/PIPELINE.md, "Textures"): the height map a scene's
// frames bend their normals by, and the tangents its textured meshes need
// for it; a step of the frame's spine (pipeline/frame_spine.h).
#include <string>

#include "image/image.h"
#include "scene/scene.h"

namespace facet {

// Makes scene.bumpMap `heights`, the greyscale map `path` names
// (pipeline/displacement.h reads it), and gives every mesh with TEXCOORD_0
// and no tangents computed ones, priced against the scene budget first
// (refused naming material.bumpMap and the mesh). Renews the scene's identity.
void useBumpMap(Scene& scene, const std::string& path, const Image& heights);

}  // namespace facet
