#include "pipeline/painters_order.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/mat4x4.hpp>

#include "pipeline/frame_inputs.h"

namespace facet {

std::vector<double> farthestEyeDepths(const Scene& scene, const FrameInputs& frame) {
  std::vector<double> farthest;
  for (const FrameInstance& instance : frame.instances) {
    const Mesh& mesh = scene.meshes[static_cast<std::size_t>(instance.mesh)];
    const glm::dmat4 eyeFromModel = glm::dmat4(frame.eyeFromWorld) * glm::dmat4(instance.worldFromModel);  // EM·TM
    const glm::dvec4 row(eyeFromModel[0][2], eyeFromModel[1][2], eyeFromModel[2][2], eyeFromModel[3][2]);  // z_eye of (p, 1)
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      double d = -std::numeric_limits<double>::infinity();
      bool finite = true;
      for (std::size_t k = 0; k < 3; ++k) {
        const glm::dvec3 p(mesh.positions[mesh.indices[t + k]]);
        const double depth = row.x * p.x + row.y * p.y + row.z * p.z + row.w;  // d = z_eye: the course's eye looks along +z
        finite &= std::isfinite(depth);
        d = std::max(d, depth);
      }
      farthest.push_back(finite ? d : std::numeric_limits<double>::infinity());
    }
  }
  return farthest;
}

std::vector<std::uint32_t> paintersOrder(const Scene& scene, const FrameInputs& frame) {
  const std::vector<double> farthest = farthestEyeDepths(scene, frame);
  std::vector<std::uint32_t> order(farthest.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return farthest[a] > farthest[b]; });
  return order;
}

}  // namespace facet
