// The phases of a pass on the renderer's threads (frame_buffers.h): ranges
// of vertices or triangles split evenly, tiles handed out as workers free up.
#include <algorithm>
#include <atomic>

#include "cpu/passes.h"
#include "shading/transform.h"

namespace facet::cpu {

void prepareFrame(ThreadPool& pool, FrameBuffers& buffers, const Scene& scene, const FrameInputs& frame) {
  PassVertices& v = buffers.vertices;
  v.firstVertex.clear();
  v.firstTriangle.clear();
  std::size_t vertices = 0, triangles = 0;
  for (const FrameInstance& instance : frame.instances) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    v.firstVertex.push_back(vertices);
    v.firstTriangle.push_back(triangles);
    vertices += mesh.positions.size();
    triangles += mesh.indices.size() / 3;
  }
  v.firstVertex.push_back(vertices);
  v.firstTriangle.push_back(triangles);
  v.world.resize(vertices);
  v.clip.resize(vertices);
  v.flags.resize(vertices);
  if (buffers.workers.size() < static_cast<std::size_t>(pool.size())) buffers.workers.resize(static_cast<std::size_t>(pool.size()));
  // An instance's vertices at a time, its matrix in a local that the stores cannot alias.
  forEachRange(pool, frame.instances.size() == 0 ? 0 : vertices, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t g = begin, instance = 0; g < end;) {
      while (g >= v.firstVertex[instance + 1]) ++instance;
      const std::size_t first = v.firstVertex[instance], last = std::min(end, v.firstVertex[instance + 1]);
      const glm::mat4 worldFromModel = frame.instances[instance].worldFromModel;
      const glm::vec3* positions = scene.meshes[static_cast<std::size_t>(frame.instances[instance].mesh)].positions.data();
      for (; g < last; ++g) v.world[g] = glm::vec3(transformPoint(worldFromModel, positions[g - first]));
    }
  });
}

void forEachTile(ThreadPool& pool, const TileGrid& grid, FunctionRef<void(int, int, const TileRect&)> work) {
  std::atomic<int> next{0};
  pool.run([&](int worker) {
    for (int tile = next++; tile < grid.count(); tile = next++) work(worker, tile, grid.rect(tile));
  });
}

}  // namespace facet::cpu
