#pragma once
#include "scene/scene.h"

namespace facet {

// The course's vertex-normal rule: each vertex normal is the normalized sum
// of the normals of the triangles around it, each weighted by its area
// (the unnormalized cross product carries twice the area). A vertex touching
// only degenerate triangles gets (0, 0, 1). Replaces mesh.normals.
void computeVertexNormals(Mesh& mesh);

}  // namespace facet
