#pragma once
// Marching cubes (Lorensen and Cline 1987): the iso-surface f = isoValue of a
// volume as a triangle mesh (renderer/PIPELINE.md, "Marching cubes").
#include "scene/scene.h"
#include "scene/volume.h"

namespace facet {

// The surface between samples ≥ isoValue (inside) and samples < isoValue
// (outside), in the volume's model space (the box [0, extent]): one vertex
// per grid edge it crosses, where linear interpolation along the edge
// reaches isoValue, shared by every triangle on that edge; normals the
// normalized −gradient interpolated likewise (pointing outside); triangles
// counter-clockwise seen from outside. Ambiguous faces are decided by the
// face alone, so neighbouring cubes agree and the mesh has no holes: every
// edge inside the box is shared by exactly two triangles.
Mesh marchingCubes(const Volume& volume, float isoValue);

}  // namespace facet
