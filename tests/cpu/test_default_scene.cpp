// The default scene through the CPU backend in every shading mode, with and
// without shadows. The PNGs are written to the build folder to be looked at.
#include <filesystem>
#include <set>
#include <string>

#include <doctest/doctest.h>

#include "cpu_test_scenes.h"
#include "image/png.h"
#include "pipeline/frame_inputs.h"
#include "scene/default_scene.h"

using namespace facet;

TEST_CASE("default scene: every shading mode with and without shadows renders the scene, and shadows darken the ground") {
  const Scene scene = makeDefaultScene();
  std::filesystem::create_directories(FACET_TEST_OUTPUT);
  for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
    Image withShadows, without;
    for (bool shadows : {true, false}) {
      RenderSettings s;
      s.width = 320;
      s.height = 240;
      s.shading = mode;
      s.shadows.enabled = shadows;
      const Image image = test::renderCpu(scene, s);
      const std::string name = std::string(kShadingModeNames[static_cast<std::size_t>(mode)]) + (shadows ? "_shadows" : "_no_shadows");
      writePng(std::string(FACET_TEST_OUTPUT) + "/default_cpu_" + name + ".png", image);
      CAPTURE(name);
      // Not a blank image: the top rows are background, the centre is not, and it has many colours.
      const Rgba8 background = test::expectedPixel(s.background);
      CHECK(image.at(5, 235) == background);
      CHECK_FALSE(image.at(160, 100) == background);
      std::set<int> colours;
      for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 320; ++x) colours.insert(image.at(x, y).r << 16 | image.at(x, y).g << 8 | image.at(x, y).b);
      CHECK(colours.size() > 200);
      (shadows ? withShadows : without) = image;
    }
    // Shadows only ever remove light.
    int darker = 0, brighter = 0;
    for (int y = 0; y < 240; ++y)
      for (int x = 0; x < 320; ++x) {
        darker += withShadows.at(x, y).r < without.at(x, y).r;
        brighter += withShadows.at(x, y).r > without.at(x, y).r;
      }
    CHECK(darker > 1000);
    CHECK(brighter == 0);
  }
}
