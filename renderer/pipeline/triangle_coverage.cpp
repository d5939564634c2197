#include "pipeline/triangle_coverage.h"

#include <string>

#include "common/error.h"

namespace facet {

SingleTriangle singleTriangle(const Scene& scene, const FrameInputs& frame, std::uint32_t triangle) {
  const std::vector<std::size_t> first = firstTriangles(scene, frame);
  if (triangle == 0 || triangle > first.back())
    throw Error("triangle " + std::to_string(triangle) + ": the frame has " + std::to_string(first.back()) + " triangles, numbered from 1");
  const std::size_t listed = triangle - 1;
  const std::size_t instanceIndex = instanceOfTriangle(first, listed);
  const FrameInstance& instance = frame.instances[instanceIndex];
  const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
  const std::size_t local = listed - first[instanceIndex];

  SingleTriangle single;
  single.scene.source = scene.source + ", triangle " + std::to_string(triangle);
  single.scene.materials = scene.materials;
  single.scene.textures = scene.textures;
  Mesh alone;
  alone.name = mesh.name;
  alone.material = mesh.material;
  for (std::uint32_t k = 0; k < 3; ++k) {
    const std::uint32_t i = mesh.indices[3 * local + k];
    alone.positions.push_back(mesh.positions[i]);
    alone.normals.push_back(mesh.normals[i]);
    if (!mesh.texcoords.empty()) alone.texcoords.push_back(mesh.texcoords[i]);
    if (!mesh.texcoords1.empty()) alone.texcoords1.push_back(mesh.texcoords1[i]);
    if (!mesh.colors.empty()) alone.colors.push_back(mesh.colors[i]);
    if (!mesh.tangents.empty()) alone.tangents.push_back(mesh.tangents[i]);
    alone.indices.push_back(k);
  }
  single.scene.meshes.push_back(std::move(alone));
  single.scene.instances.push_back({0, instance.worldFromModel});

  // The same frame with that triangle alone: drawn as an opaque one (a
  // blended triangle counts as one in the counts, which ignore every test),
  // one sample at each pixel centre, no shadow maps.
  FrameInputs& f = single.frame;
  f = frame;
  FrameInstance drawn = instance;
  drawn.mesh = 0;
  f.instances = {drawn};
  CourseMaterial& material = f.materials[static_cast<std::size_t>(instance.material)];
  material.blended = false;
  material.masked = false;
  f.hsr = HiddenSurface::ZBuffer;
  f.paintersOrder.clear();
  f.transparentOrder.clear();
  f.samples.clear();
  f.sampleOffset = glm::vec2(0.0f);
  f.areaAveraged = false;
  f.shadowLayerCount = 0;
  for (FrameLight& light : f.lights) light.hasShadowMap = false;
  f.volume.placed = nullptr;
  return single;
}

Image coverageImage(const std::vector<std::uint32_t>& counts, const std::vector<std::uint32_t>& kept, std::uint32_t triangle, int width,
                    int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t pixel = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      if (counts[pixel] == 0) image.at(x, y) = {0, 0, 0, 255};
      else if (kept[pixel] == triangle) image.at(x, y) = {255, 230, 0, 255};
      else image.at(x, y) = {150, 70, 0, 255};
    }
  return image;
}

}  // namespace facet
