#pragma once
// The scenes `facet bench` renders, built in code with a manual camera and
// manual lights, so that a frame depends on nothing but its name and size:
// the named scenes of `--scenes`, and the sphere `--sweep` grows.
#include <string>
#include <vector>

#include "scene/scene.h"
#include "settings/render_settings.h"

namespace facet {

struct BenchScene {
  std::string name;
  Scene scene;
  RenderSettings settings;
};

inline constexpr int kSphere100k = 159;  // 4·159·158 = 100 488 triangles
inline constexpr int kSphere1M = 500;    // 4·500·499 = 998 000 triangles

// A unit sphere of `level` bands (4·level·(level-1) triangles) on a ground
// plane, Phong shading. spotLights 0: one point light, no shadows; N > 0: N
// spot lights spaced evenly around the sphere, all aimed at it, each with a
// mapSize² shadow map and PCF r = 1, each 1/N as bright (the same exposure).
BenchScene sphereScene(const std::string& name, int level, int spotLights, int width, int height, int mapSize = 2048);

// The names `--scenes` takes, in the order bench runs them.
std::vector<std::string> allSceneNames();

// One of allSceneNames(); throws facet::Error for any other name.
BenchScene makeBenchScene(const std::string& name, int width, int height);

}  // namespace facet
