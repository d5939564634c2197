// Camera-facing quads as a blended, unlit mesh of the scene.
#include "particles/sprites.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

#include <glm/geometric.hpp>

#include "image/mipmap.h"

namespace facet {

Image softDisc(int side) {
  Image image(side, side);
  const float half = 0.5f * static_cast<float>(side);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const float dx = (static_cast<float>(x) + 0.5f - half) / half, dy = (static_cast<float>(y) + 0.5f - half) / half;
      const float r2 = dx * dx + dy * dy;
      const float a = r2 < 1.0f ? (1.0f - r2) * (1.0f - r2) : 0.0f;
      image.at(x, y) = {255, 255, 255, static_cast<std::uint8_t>(a * 255.0f + 0.5f)};
    }
  return image;
}

void addSprites(Scene& scene, const std::vector<Sprite>& sprites, const CameraSettings& camera, const Image& sprite, SpriteBlending blending,
                bool castsShadow, const std::string& name) {
  if (sprites.empty()) return;
  // The eye's axes (the course's eye matrix): n toward the eye, u to the right, v up.
  const glm::vec3 n = glm::normalize(camera.eye - camera.reference);
  const glm::vec3 u = glm::normalize(glm::cross(camera.up, n));
  const glm::vec3 v = glm::cross(n, u);
  // Farthest first: the largest distance along −n from the eye.
  std::vector<std::size_t> order(sprites.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<float> depth(sprites.size());
  for (std::size_t i = 0; i < sprites.size(); ++i) depth[i] = glm::dot(camera.eye - sprites[i].center, n);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });

  Mesh mesh;
  mesh.name = name;
  mesh.sprites = true;
  mesh.positions.reserve(4 * sprites.size());
  mesh.normals.reserve(4 * sprites.size());
  mesh.texcoords.reserve(4 * sprites.size());
  mesh.colors.reserve(4 * sprites.size());
  mesh.indices.reserve(6 * sprites.size());
  const glm::vec2 corners[4] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}};
  for (const std::size_t i : order) {
    const Sprite& s = sprites[i];
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    for (const glm::vec2 c : corners) {
      mesh.positions.push_back(s.center + (c.x * s.size) * u + (c.y * s.size) * v);
      mesh.normals.push_back(n);
      mesh.texcoords.push_back(c + 0.5f);
      mesh.colors.push_back(s.color);
    }
    for (const std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + k);
  }

  Texture texture;
  texture.name = name + " sprite";
  texture.image = sprite;
  texture.encoding = TexelEncoding::Srgb;
  texture.mips = mipLevels(texture.image, texture.encoding);
  texture.sampler.wrapS = texture.sampler.wrapT = Wrap::ClampToEdge;
  scene.textures.push_back(std::move(texture));

  Material material;
  material.name = name;
  material.baseColor = glm::vec4(1.0f);
  material.baseColorTexture = static_cast<int>(scene.textures.size()) - 1;
  material.alphaMode = AlphaMode::Blend;
  material.doubleSided = true;
  material.unlit = true;
  material.additive = blending == SpriteBlending::Additive;
  material.castsShadow = castsShadow;
  material.metallic = 0.0f;
  scene.materials.push_back(std::move(material));
  scene.addObject(std::move(mesh), static_cast<int>(scene.materials.size()) - 1, glm::mat4(1.0f));
}

}  // namespace facet
