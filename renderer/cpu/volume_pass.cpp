// Volume ray casting over the CPU backend's frame, a row of pixels per task.
#include "cpu/volume_pass.h"

#include <glm/mat4x4.hpp>

#include "shading/blending.h"

namespace facet::cpu {

RayCastCounts volumePass(ThreadPool& pool, const FrameInputs& frame, const std::vector<float>& depth, ColorBuffer& color) {
  const Scene::PlacedVolume& placed = *frame.volume.placed;
  const RayCastVolume volume(*placed.data, placed.transfer, {frame.volume.step, frame.volume.earlyTermination, frame.volume.emptySpaceSkipping});
  // Window (NDC x, y and the z-buffer's z) to the volume's model space, in double: (PM·EM·TM_volume)^-1.
  const glm::dmat4 modelFromClip = glm::inverse(glm::dmat4(frame.clipFromWorld) * glm::dmat4(placed.worldFromVolume));
  const glm::dvec4 nearClip = glm::dmat4(frame.clipFromEye) * glm::dvec4(0.0, 0.0, -static_cast<double>(frame.camera.near), 1.0);
  const double nearZ = nearClip.z / nearClip.w;
  const auto unproject = [&](double x, double y, double z) {
    const glm::dvec4 p = modelFromClip * glm::dvec4(x, y, z, 1.0);
    return glm::vec3(glm::dvec3(p) / p.w);
  };
  std::vector<RayCastCounts> rows(static_cast<std::size_t>(frame.height));
  forEachRange(pool, static_cast<std::size_t>(frame.height), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t y = begin; y < end; ++y) {
      const int py = static_cast<int>(y);
      const double yNdc = (py + 0.5) / (0.5 * frame.height) - 1.0;
      for (int px = 0; px < frame.width; ++px) {
        const double xNdc = (px + 0.5) / (0.5 * frame.width) - 1.0;
        const float z = depth[y * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(px)];
        const glm::vec4 cast = volume.cast(unproject(xNdc, yNdc, nearZ), unproject(xNdc, yNdc, z), rows[y]);
        if (!(cast.a > 0.0f)) continue;
        glm::vec4& held = color.at(px, py);
        const glm::vec4 behind = premultipliedOf(held, frame.blending);
        const float k = 1.0f - cast.a;
        const glm::vec4 over(glm::vec3(cast) + k * glm::vec3(behind), cast.a + k * behind.a);
        held = frame.blending == Blending::Premultiplied ? over : unstored(over, Blending::Premultiplied);
      }
    }
  });
  RayCastCounts total;
  for (const RayCastCounts& r : rows) total += r;
  return total;
}

}  // namespace facet::cpu
