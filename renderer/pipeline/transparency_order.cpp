#include "pipeline/transparency_order.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/mat4x4.hpp>

#include "pipeline/frame_inputs.h"
#include "pipeline/painters_order.h"

namespace facet {
namespace {

bool blendedInstance(const FrameInputs& frame, const FrameInstance& instance) {
  return frame.materials[static_cast<std::size_t>(instance.material)].blended;
}

// d = z_eye of the centre of the instance's world bounding box, in double (+infinity when not finite).
double centreEyeDepth(const Mesh& mesh, const FrameInputs& frame, const FrameInstance& instance) {
  const glm::dmat4 worldFromModel(instance.worldFromModel);
  glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
  for (const glm::vec3& p : mesh.positions) {
    const glm::dvec3 world(worldFromModel * glm::dvec4(glm::dvec3(p), 1.0));
    low = glm::min(low, world);
    high = glm::max(high, world);
  }
  const glm::dvec4 eye = glm::dmat4(frame.eyeFromWorld) * glm::dvec4(0.5 * (low + high), 1.0);
  return std::isfinite(eye.z) ? eye.z : std::numeric_limits<double>::infinity();  // the course's eye looks along +z
}

}  // namespace

std::vector<std::uint32_t> transparentOrder(const Scene& scene, const FrameInputs& frame, TransparencySort sort) {
  const std::vector<std::size_t> firstTriangle = firstTriangles(scene, frame);
  std::vector<std::uint32_t> order;
  if (sort == TransparencySort::Triangle) {
    const std::vector<double> farthest = farthestEyeDepths(scene, frame);
    for (std::size_t i = 0; i < frame.instances.size(); ++i)
      if (blendedInstance(frame, frame.instances[i]))
        for (std::size_t t = firstTriangle[i]; t < firstTriangle[i + 1]; ++t) order.push_back(static_cast<std::uint32_t>(t));
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return farthest[a] > farthest[b]; });
    return order;
  }
  std::vector<std::size_t> instances;
  std::vector<double> depth(frame.instances.size());
  for (std::size_t i = 0; i < frame.instances.size(); ++i) {
    if (!blendedInstance(frame, frame.instances[i])) continue;
    instances.push_back(i);
    depth[i] = centreEyeDepth(scene.meshes[static_cast<std::size_t>(frame.instances[i].mesh)], frame, frame.instances[i]);
  }
  std::stable_sort(instances.begin(), instances.end(), [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });
  for (const std::size_t i : instances)
    for (std::size_t t = firstTriangle[i]; t < firstTriangle[i + 1]; ++t) order.push_back(static_cast<std::uint32_t>(t));
  return order;
}

}  // namespace facet
