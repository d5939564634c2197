// Pass 1 of the course's 2-pass shadow algorithm: a depth-only z-buffer pass
// from the light into an S×S float map, one per face.
#include <vector>

#include "cpu/passes.h"
#include "cpu/interpolation.h"
#include "cpu/rasterize.h"
#include "cpu/vertex_math.h"

namespace facet::cpu {

void shadowPass(const Scene& scene, const FrameInputs& frame, const FrameLight& light, int face, int rowBegin, int rowEnd,
                ShadowMaps& maps) {
  const glm::mat4& lightClipFromWorld = light.frustum.clipFromWorld[static_cast<std::size_t>(face)];
  float* depth = maps.layer(light.shadowLayer + face);
  const int size = maps.size;
  const float half = 0.5f * static_cast<float>(size);
  std::vector<ClipVertex> clip;
  std::vector<WindowVertex> window, triangles;
  for (const FrameInstance& instance : frame.instances) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    // Vertex stage: clip = lightClipFromWorld · (TM · p), both products in the fixed order.
    clip.resize(mesh.positions.size());
    window.resize(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const glm::vec4 world = transformPoint(instance.worldFromModel, mesh.positions[v]);
      clip[v].clip = transformPoint(lightClipFromWorld, glm::vec3(world));
      window[v] = toWindow(clip[v], half, half, 0);
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
      triangles.clear();
      clipTriangle(clip[i0], clip[i1], clip[i2], window[i0], window[i1], window[i2], half, half, 0, triangles);
      for (std::size_t k = 0; k < triangles.size(); k += 3) {
        TriangleSetup setup;
        if (!setupTriangle(triangles[k], triangles[k + 1], triangles[k + 2], size, size, setup)) continue;
        Interpolation interpolation(triangles[k], triangles[k + 1], triangles[k + 2]);
        rasterize(setup, rowBegin, rowEnd, [&](int px, int py) {
          const float z = interpolation.at(px, py);
          float& stored = depth[static_cast<std::size_t>(py) * static_cast<std::size_t>(size) + static_cast<std::size_t>(px)];
          if (z < stored) stored = z;
        });
      }
    }
  }
}

}  // namespace facet::cpu
