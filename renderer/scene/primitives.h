#pragma once
// Procedural primitives in model space, centred at the origin, with outward
// unit normals and counter-clockwise (front-facing) winding seen from outside.
#include "scene/scene.h"

namespace facet {

// UV sphere of radius 1 with `level` latitude bands (>= 2) and 2·level
// longitude segments: 4·level·(level - 1) triangles.
Mesh makeSphere(int level);

// Cube [-1, 1]³, four vertices and one normal per face: 12 triangles.
Mesh makeCube();

// Square [-1, 1]² in the plane y = 0, normal +y, cut into n×n quads.
Mesh makePlane(int subdivisions = 1);

// Cylinder of radius 1 from y = -1 to y = 1 with caps, `segments` around.
Mesh makeCylinder(int segments = 48);

// Torus around the y axis: ring radius `major`, tube radius `minor`.
Mesh makeTorus(float major = 0.7f, float minor = 0.3f, int ringSegments = 64, int tubeSegments = 24);

}  // namespace facet
