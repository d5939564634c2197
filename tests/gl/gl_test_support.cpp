#include "gl_test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "image/png.h"

namespace facet::test {

RenderSettings smallSettings(ShadingMode shading, bool shadows, bool cullBackFaces) {
  RenderSettings settings;
  settings.width = 160;
  settings.height = 120;
  settings.shading = shading;
  settings.shadows.enabled = shadows;
  settings.shadows.mapSize = 512;
  settings.cullBackFaces = cullBackFaces;
  return settings;
}

Image renderHeadless(const std::string& name, const Scene& scene, const FrameInputs& frame, GlContextKind kind) {
  Image image = makeGlRenderer(kind)->render(scene, frame).image;
  writeTestImage(name, image);
  return image;
}

void writeTestImage(const std::string& name, const Image& image) { writePng(std::string(FACET_GL_TEST_IMAGES) + "/" + name + ".png", image); }

glm::vec2 windowOf(const FrameInputs& frame, glm::vec3 world) {
  const glm::vec4 clip = frame.clipFromWorld * glm::vec4(world, 1.0f);
  const glm::vec4 window = frame.windowFromNdc * glm::vec4(glm::vec3(clip) / clip.w, 1.0f);
  return {window.x, window.y};
}

glm::ivec2 pixelOf(const FrameInputs& frame, glm::vec3 world) {
  const glm::vec2 window = windowOf(frame, world);
  return {static_cast<int>(std::floor(window.x)), static_cast<int>(std::floor(window.y))};
}

double luma(Rgba8 pixel) { return 0.2126 * pixel.r + 0.7152 * pixel.g + 0.0722 * pixel.b; }

int encodedByte(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::floor(encoded * 255.0 + 0.5));
}

Rgba8 encodedPixel(glm::vec3 linear) {
  return {static_cast<std::uint8_t>(encodedByte(linear.r)), static_cast<std::uint8_t>(encodedByte(linear.g)),
          static_cast<std::uint8_t>(encodedByte(linear.b)), 255};
}

std::string describe(Rgba8 p) {
  char text[48];
  std::snprintf(text, sizeof text, "(%d, %d, %d, %d)", p.r, p.g, p.b, p.a);
  return text;
}

BoundingSphere boundingSphere(const Scene& scene, const FrameInputs& frame, std::size_t instance) {
  const FrameInstance& fi = frame.instances[instance];
  const Mesh& mesh = scene.meshes[static_cast<std::size_t>(fi.mesh)];
  Bounds bounds;
  for (glm::vec3 p : mesh.positions) bounds.include(glm::vec3(fi.worldFromModel * glm::vec4(p, 1.0f)));
  BoundingSphere sphere{bounds.center(), 0.0f};
  for (glm::vec3 p : mesh.positions) sphere.radius = std::max(sphere.radius, glm::length(glm::vec3(fi.worldFromModel * glm::vec4(p, 1.0f)) - sphere.center));
  return sphere;
}

std::size_t instanceWithMaterial(const Scene& scene, const FrameInputs& frame, const std::string& material) {
  for (std::size_t i = 0; i < frame.instances.size(); ++i) {
    const int m = scene.meshes[static_cast<std::size_t>(frame.instances[i].mesh)].material;
    if (m >= 0 && scene.materials[static_cast<std::size_t>(m)].name == material) return i;
  }
  throw std::runtime_error("no instance with material '" + material + "'");
}

}  // namespace facet::test
