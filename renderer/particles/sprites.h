#pragma once
// The course's sprites "that always face the user": camera-facing quads,
// each a particle (or a volume's splat), added to a scene as one mesh of
// blended, unlit triangles, so both rasterizers draw them in the
// transparency pass: depth-tested against the scene's z-buffer without
// writing it, back to front (renderer/PIPELINE.md, "Sprites").
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "image/image.h"
#include "vocabulary/emitter.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

struct Sprite {
  glm::vec3 center{0.0f};  // world space
  float size = 0.0f;       // world units: the quad's side
  glm::vec4 color{1.0f};   // linear RGB and alpha, multiplied by the texture's texel
};

// A soft disc `side` pixels across: white, α = (1 − r²)² inside the unit
// circle r ≤ 1 (r from the image's centre to the texel's), 0 outside.
Image softDisc(int side);

// Appends `sprites` to `scene` as one mesh, each a square of its size
// centred on it in the plane parallel to the view plane (spanned by the
// resolved camera's u and v), sorted farthest first by eye depth (a stable
// sort: equal depths keep their order), two counter-clockwise triangles
// each, double-sided; with a blended unlit material of base colour white,
// COLOR_0 the sprite's colour and the base colour texture `sprite` (an
// sRGB image with alpha, mipmapped here). `camera` must be resolved
// (pipeline/view_setup.h). Adds nothing for no sprites.
void addSprites(Scene& scene, const std::vector<Sprite>& sprites, const CameraSettings& camera, const Image& sprite, SpriteBlending blending,
                bool castsShadow, const std::string& name);

}  // namespace facet
