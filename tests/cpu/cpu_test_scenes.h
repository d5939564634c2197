#pragma once
// Small scenes and settings for CPU backend tests, checkable by hand.
#include <glm/vec3.hpp>

#include "render/renderer.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet::test {

// The square [-2,2]² of the plane y = 0, cut into n×n quads, one material.
Scene groundScene(int subdivisions, glm::vec3 baseColor);

// groundScene(8, grey) plus a cube of half-size 0.3 centred 0.8 above the origin (its underside 0.5 above the ground).
Scene occluderScene();

// Looks straight down -y from (0, 10, 0) with a parallel box of width 4,
// image size×size: pixel (px, py) centre sees world x = (px+0.5)·4/size - 2,
// z = 2 - (py+0.5)·4/size (image up is world -z).
RenderSettings topDownSettings(int size);
glm::vec3 worldAtPixel(int px, int py, int size);

// topDownSettings with `light` as the only light, casting hard shadows into a 512² map.
RenderSettings shadowedTopDownSettings(int size, Light light);

// Renders with the CPU backend (two threads).
Image renderCpu(const Scene& scene, const RenderSettings& settings);

// sRGB encode + 8-bit rounding of a linear colour, written out by hand from
// IEC 61966-2-1 (not the renderer's code).
Rgba8 expectedPixel(glm::vec3 linear);

}  // namespace facet::test
