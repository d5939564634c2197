#pragma once
#include "scene/scene.h"

namespace facet {

// Tangents for a mesh with texture coordinate set `set` (TEXCOORD_0 or
// TEXCOORD_1, the normal texture's) and no TANGENT (renderer/PIPELINE.md,
// "Normal textures"): each triangle's ∂P/∂s and ∂P/∂t from its
// edges and texture-coordinate differences (Lengyel), summed at its
// vertices; at each vertex T is that sum made perpendicular to N and unit,
// and w = ±1 makes B = w·(N × T) point against the summed ∂P/∂t: glTF's t
// grows down the image, and a normal texture's +y points up it (the file's
// TANGENT, as exporters write it, says the same for an unmirrored layout). A vertex whose
// triangles give no direction gets a unit vector perpendicular to N.
// Fills mesh.tangents, one per position. Not MikkTSpace (no Debian package
// provides it): the two agree where a mesh's texture layout has no seams
// between mirrored or split vertices.
void computeVertexTangents(Mesh& mesh, int set = 0);

// The set a mesh's tangents follow: its material's normal texture's, else TEXCOORD_0.
int tangentSetOf(const Scene& scene, const Mesh& mesh);

}  // namespace facet
