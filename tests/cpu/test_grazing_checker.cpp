// Texture mapping's reason for mipmaps (renderer/PIPELINE.md, "Textures"): a
// checker floor seen at a grazing angle, against a supersampled reference
// (8×8 bilinear samples per pixel, averaged in linear light), as the camera
// steps forward a quarter of a square at a time. Shimmer is how much a
// filter's error changes from one step to the next: what moves on screen
// that the reference does not show moving.
#include <cmath>
#include <vector>

#include <doctest/doctest.h>

#include "cpu_test_scenes.h"
#include "image/srgb.h"
#include "pipeline/view_setup.h"
#include "scene/load_scene.h"

using namespace facet;

namespace {

constexpr int kWidth = 160, kHeight = 90, kSupersample = 8, kFrames = 4;

// One channel (green) of each pixel in linear light, rows bottom first.
std::vector<double> linearGreen(const Image& image) {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.height()));
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) out.push_back(srgbTables().decoded[image.at(x, y).g]);
  return out;
}

// The image at kWidth × kHeight, or its kSupersample² box average.
std::vector<double> render(const Scene& scene, RenderSettings s, TextureFilter filter, int supersample) {
  s.textures.filter = filter;
  s.width = kWidth * supersample, s.height = kHeight * supersample;
  const std::vector<double> fine = linearGreen(test::renderCpu(scene, s));
  std::vector<double> out(static_cast<std::size_t>(kWidth * kHeight), 0.0);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      out[static_cast<std::size_t>((y / supersample) * kWidth + x / supersample)] += fine[static_cast<std::size_t>(y * s.width + x)];
  for (double& v : out) v /= supersample * supersample;
  return out;
}

}  // namespace

TEST_CASE("a grazing checker floor: trilinear stays nearer the supersampled reference than bilinear, and shimmers less as the camera moves") {
  const Scene scene = loadScene(std::string(FACET_ASSETS) + "/scenes/grazing_checker.gltf");
  RenderSettings base;
  base.width = kWidth, base.height = kHeight;
  base.shadows.enabled = false;
  base.camera = resolveCamera(scene, base);
  const double background = srgbTables().decoded[encodePixel(base.background).g];

  struct Measure {
    double squaredError = 0, shimmer = 0;
  } bilinear, trilinear;
  std::vector<double> previous[3];
  long floorPixels = 0, shimmerSamples = 0;
  for (int frame = 0; frame < kFrames; ++frame) {
    RenderSettings s = base;
    const glm::vec3 step{0.0f, 0.0f, -0.0625f * static_cast<float>(frame)};  // a quarter of a 25 cm square
    s.camera.eye += step, s.camera.reference += step;
    const std::vector<double> images[3] = {render(scene, s, TextureFilter::Bilinear, kSupersample), render(scene, s, TextureFilter::Bilinear, 1),
                                           render(scene, s, TextureFilter::Trilinear, 1)};
    const std::vector<double>& truth = images[0];
    for (std::size_t i = 0; i < truth.size(); ++i) {
      if (std::fabs(truth[i] - background) < 1e-4) continue;  // sky
      ++floorPixels;
      bilinear.squaredError += (images[1][i] - truth[i]) * (images[1][i] - truth[i]);
      trilinear.squaredError += (images[2][i] - truth[i]) * (images[2][i] - truth[i]);
      if (frame == 0) continue;
      ++shimmerSamples;
      const double truthChange = truth[i] - previous[0][i];
      bilinear.shimmer += std::fabs(images[1][i] - previous[1][i] - truthChange);
      trilinear.shimmer += std::fabs(images[2][i] - previous[2][i] - truthChange);
    }
    for (int k = 0; k < 3; ++k) previous[k] = images[k];
  }
  REQUIRE(floorPixels > kFrames * kWidth * kHeight / 4);
  const double bilinearRmse = std::sqrt(bilinear.squaredError / static_cast<double>(floorPixels));
  const double trilinearRmse = std::sqrt(trilinear.squaredError / static_cast<double>(floorPixels));
  const double n = static_cast<double>(shimmerSamples);
  MESSAGE((floorPixels / kFrames) << " floor pixels a frame; RMSE against the 8x8-supersampled reference (linear green): bilinear "
                                << bilinearRmse << ", trilinear " << trilinearRmse << "; shimmer (mean change of the error per step): bilinear "
                                << bilinear.shimmer / n << ", trilinear " << trilinear.shimmer / n);
  CHECK(trilinearRmse < 0.6 * bilinearRmse);
  CHECK(trilinear.shimmer < 0.6 * bilinear.shimmer);
}
