#pragma once
#include "scene/scene.h"

namespace facet {

// builtin:cornell: the Cornell box of the ray-tracing chapter
// (renderer/PIPELINE.md, "Ray tracing"): white floor, ceiling and back wall, a
// red wall on the left and a green one on the right, a mirror sphere
// (metallic, smooth: k_r = O_d) and a glass sphere (transmission 1, index of
// refraction 1.5), a spherical light (radius 0.08: the ray tracer's soft
// shadows) under a glowing ceiling panel, and a camera
// looking in through the open side. Built in code; the builtin spheres are
// traced as spheres.
Scene makeCornellBox();

}  // namespace facet
