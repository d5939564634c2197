#pragma once
// Bump mapping (renderer/PIPELINE.md, section 8): the height map a scene's
// frames bend their normals by, loaded once with the scene, and the
// tangents its textured meshes need for it.
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

// Makes scene.bumpMap the height map `material.bumpMap` names (a greyscale
// PNG, refused naming the key and the file otherwise), and gives every mesh
// with TEXCOORD_0 and no tangents computed ones, priced against the scene
// budget first; nothing for an empty name. Renews the scene's identity.
void useBumpMap(Scene& scene, const MaterialOverrides& material);

}  // namespace facet
