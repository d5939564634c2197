#pragma once
// Displacement mapping (renderer/PIPELINE.md, "Textures"): every textured mesh
// subdivided, its vertices moved along their normals by a height map, and
// its normals recomputed, once, before either backend draws: a step of the
// frame's spine (pipeline/frame_spine.h).
#include <string>

#include "image/image.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

// The height map in `path`: refused when it does not decode or a pixel is not grey (R = G = B).
Image loadHeightMap(const std::string& path);

// h at texture coordinates st: bilinear, REPEAT, t = 0 at the image's top, grey / 255.
double heightAt(const Image& heights, double s, double t);

// Subdivides and displaces every mesh of `scene` with TEXCOORD_0 (warning
// for the others) and renews its identity; refused, before anything is
// made, when the triangles would not fit the scene budget.
void displaceMeshes(Scene& scene, const Image& heights, float scale, int subdivisions);

// The key a scene's displacement was made with (Scene::displacement): the three settings, or "" for none.
std::string displacementKey(const MaterialOverrides& material);

}  // namespace facet
