#pragma once
// What the lit pass interpolates per shading mode, after a window vertex's
// x, y, z, 1/w: the fast renderer's packed vertices and the reference's
// clip vertices lay them out alike.
//   Phong:   world position 0-2, normal 3-5, texture coordinates 6-7
//   Gouraud: front diffuse 0-2, front specular 3-5, back diffuse 6-8,
//            back specular 9-11, texture coordinates 12-13
//   flat:    texture coordinates 0-1 (the illumination is per triangle)
#include "settings/render_settings.h"

namespace facet::cpu {

struct VaryingLayout {
  int count = 0;  // varyings in use
  int uv = 0;     // the first texture coordinate
};

constexpr VaryingLayout varyingLayout(ShadingMode mode) {
  switch (mode) {
    case ShadingMode::Phong: return {8, 6};
    case ShadingMode::Gouraud: return {14, 12};
    default: return {2, 0};
  }
}

}  // namespace facet::cpu
